#include "io/read_obj.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <utility>

#include "io/input_file_limits.h"
#include "sim/input_error.h"
#include "sim/input_limits.h"
#include "temporary_folder.h"

namespace {

using Faces = std::vector<std::vector<int>>;

class ReadObj : public ::testing::Test {
 protected:
  std::string write(const std::string& text) {
    const std::string path = folder_.file("mesh.obj");
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  wobble::ObjMesh read(const std::string& text) { return wobble::read_obj(write(text)); }
  // The one-line message read_obj throws for `text`, or "" when it throws nothing.
  std::string error(const std::string& text) {
    try {
      read(text);
    } catch (const wobble::InputError& e) {
      return e.what();
    }
    return "";
  }
  // The message names the file and the line, says what was found, and fits on one line.
  void expect_error(const std::string& text, const std::string& line, const std::string& what) {
    const std::string message = error(text);
    SCOPED_TRACE(text);
    EXPECT_EQ(message.rfind(folder_.file("mesh.obj") + ": " + line, 0), 0u) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }

  wobble::testing::TemporaryFolder folder_;
};

const char* const square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST_F(ReadObj, PositionsAndPolygonsAsWrittenZeroBased) {
  const wobble::ObjMesh mesh = read(std::string(square) + "v 0.5 2 -0.25\nf 1 2 3 4\nf 4 3 5\n");
  ASSERT_EQ(mesh.V.rows(), 5);
  ASSERT_EQ(mesh.V.cols(), 3);
  EXPECT_EQ(mesh.V.row(4), Eigen::RowVector3d(0.5, 2, -0.25));
  EXPECT_EQ(mesh.V.row(2), Eigen::RowVector3d(1, 1, 0));
  EXPECT_EQ(mesh.faces, (Faces{{0, 1, 2, 3}, {3, 2, 4}}));
  EXPECT_EQ(mesh.uv.size(), 0) << "no vt, no uv";
}

TEST_F(ReadObj, AllCornerFormsGiveTheSameFacesAndTheFirstUvWins) {
  const std::string vertices = std::string(square) + "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n";
  const wobble::ObjMesh mesh =
      read(vertices + "vn 0 0 1\nf 1/1/1 2/2/1 3/3/1\nf 1//1 3//1 4//1\n" + "f 3/5 4/4 1/5\n");
  EXPECT_EQ(mesh.faces, (Faces{{0, 1, 2}, {0, 2, 3}, {2, 3, 0}}));
  ASSERT_EQ(mesh.uv.rows(), 4);
  ASSERT_EQ(mesh.uv.cols(), 2);
  EXPECT_EQ(mesh.uv.row(0), Eigen::RowVector2d(0, 0));  // not 0.5 0.5 from the third face
  EXPECT_EQ(mesh.uv.row(2), Eigen::RowVector2d(1, 1));  // not 0.5 0.5 either
  EXPECT_EQ(mesh.uv.row(3), Eigen::RowVector2d(0, 1));  // first given by the third face
}

TEST_F(ReadObj, CoordinatesAreTheCorrectlyRoundedDoubles) {
  // Hand-written number parsers are easy to get an ulp wrong: OBJ readers have read 0.75 as
  // 0.75000000000000011 and 0.3 one ulp high.
  const wobble::ObjMesh mesh = read(
      "v 0.75 0.3 0.7\nv 0.15000000000000002 1e-300 -2.5e17\n"
      "v 0 1 0\nvt 0.3 0.7\nf 1/1 2/1 3/1\n");
  EXPECT_EQ(mesh.V.row(0), Eigen::RowVector3d(0.75, 0.3, 0.7));
  EXPECT_EQ(mesh.V.row(1), Eigen::RowVector3d(0.15000000000000002, 1e-300, -2.5e17));
  EXPECT_EQ(mesh.uv.row(2), Eigen::RowVector2d(0.3, 0.7));
}

TEST_F(ReadObj, VertexThatNoCornerGivesAUvStaysAtZero) {
  const wobble::ObjMesh mesh = read(std::string(square) + "vt 0.25 0.75\nf 2/1 3/1 4/1\n");
  ASSERT_EQ(mesh.uv.rows(), 4);
  EXPECT_EQ(mesh.uv.row(0), Eigen::RowVector2d(0, 0));
  EXPECT_EQ(mesh.uv.row(1), Eigen::RowVector2d(0.25, 0.75));
}

TEST_F(ReadObj, NegativeIndicesCountBackFromTheLatestVertex) {
  const wobble::ObjMesh mesh = read(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nf -3/-2 -2/-1 -1\n"
      "v 1 1 0\nf -1 -2 -4\nl -1 -3\n");
  EXPECT_EQ(mesh.faces, (Faces{{0, 1, 2}, {3, 2, 0}, {3, 1}}));
  EXPECT_EQ(mesh.uv.row(1), Eigen::RowVector2d(1, 0));
}

TEST_F(ReadObj, EveryCornerFormAndNegativeTextureIndices) {
  // v/vt/vn, v//vn (no texture coordinate) and v/-1 (the latest vt before the line).
  const wobble::ObjMesh mesh = read(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.25 0.5\nvt 0.75 1\nvn 0 0 1\n"
      "f 1/1/1 2//1 3/-1\nvt 0.5 0.5\nf 2/-1 1 3\n");
  EXPECT_EQ(mesh.faces, (Faces{{0, 1, 2}, {1, 0, 2}}));
  EXPECT_EQ(mesh.uv.row(0), Eigen::RowVector2d(0.25, 0.5));
  EXPECT_EQ(mesh.uv.row(2), Eigen::RowVector2d(0.75, 1));
  EXPECT_EQ(mesh.uv.row(1), Eigen::RowVector2d(0.5, 0.5)) << "-1 counts from the second face";
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 1\n";
  expect_error(v + "f 1/-3 2 3\n", "line 6: ",
               "index -3 refers to none of the 2 texture coordinates, expected 1 to 2 or -1 to -2 "
               "counting back");
  expect_error(v + "f 1/x 2 3\n", "line 6: ", "'1/x' is not a vertex reference");
  expect_error(v + "f 1// 2 3\n", "line 6: ", "'1//' is not a vertex reference");
  expect_error(v + "f /1 2 3\n", "line 6: ", "'/1' is not a vertex reference");
  expect_error(v + "l 1 -4\n", "line 6: ", "refers to none of the 3 vertices");
  expect_error(v + "f 1/ 2 3\n", "line 6: ", "'1/' is not a vertex reference");
  expect_error(v + "f 1/1/ 2 3\n", "line 6: ", "'1/1/' is not a vertex reference");
  expect_error(v + "f 1/1 2/0 3\n", "line 6: ", "'2/0' is not a vertex reference");
}

TEST_F(ReadObj, TextureCoordinatesMayComeAfterTheFaceAndNormalIndicesAreFormOnly) {
  // A positive vt index, like a vertex index, is checked against every vt in the file.
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const wobble::ObjMesh mesh = read(v + "f 1/2 2/1 3\nvt 0.25 0\nvt 0.5 1\n");
  ASSERT_EQ(mesh.uv.rows(), 3);
  EXPECT_EQ(mesh.uv.row(0), Eigen::RowVector2d(0.5, 1));
  EXPECT_EQ(mesh.uv.row(1), Eigen::RowVector2d(0.25, 0));
  expect_error(v + "f 1/3 2 3\nvt 0 0\nvt 1 1\n",
               "line 4: ", "index 3 refers to none of the 2 texture coordinates, expected 1 to 2");
  // There are no normals here, and none is needed: a normal index is neither used nor resolved.
  const wobble::ObjMesh normals = read(v + "f 1//7 2//7 3//7\n");
  EXPECT_EQ(normals.faces, (Faces{{0, 1, 2}}));
  EXPECT_EQ(normals.uv.size(), 0) << "v//vn gives no texture coordinate";
  EXPECT_EQ(read(v + "vt 0.5 0.25\nf 1/1/9 2 3\n").uv.row(0), Eigen::RowVector2d(0.5, 0.25));
}

TEST_F(ReadObj, IndicesBeyondAnIntAreRefusedNotWrapped) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expect_error(v + "f 1 2 999999999\n", "line 4: ", "index 999999999 refers to none of the 3");
  expect_error(v + "f 1 2 -999999999\n", "line 4: ", "index -999999999 refers to none of the 3");
  expect_error(v + "f 1 2 4294967299\n", "line 4: ", "'4294967299' is not a vertex reference");
}

TEST_F(ReadObj, LinesAndTwoVertexFacesAreSpringsAfterTheFaces) {
  // A polyline `l a b c` is its segments a–b and b–c. The `l` elements of a group without faces
  // are kept (an OBJ library once used here lost them).
  const wobble::ObjMesh mesh =
      read(std::string(square) + "g first\nl 1 2 3\ng second\no thing\nf 4 1\nf 1 2 3\nl 4 2\n");
  EXPECT_EQ(mesh.faces, (Faces{{3, 0}, {0, 1, 2}, {0, 1}, {1, 2}, {3, 1}}));
}

TEST_F(ReadObj, IgnoresWhatASpringNetworkDoesNotNeed) {
  const wobble::ObjMesh mesh = read(
      "# a comment\r\nmtllib none.mtl\r\no cloth\r\nv 0 0 0\r\nv  1\t0 0 \r\nv 0 1 0 0.5 0.5 "
      "0.5\r\nvn 0 0 1\r\nusemtl red\r\ns off\r\np 1\r\nf 1 2 3\r\n");
  EXPECT_EQ(mesh.V.rows(), 3);
  EXPECT_EQ(mesh.V.row(1), Eigen::RowVector3d(1, 0, 0));
  EXPECT_EQ(mesh.faces, (Faces{{0, 1, 2}}));
}

TEST_F(ReadObj, MissingFileIsNamed) {
  const std::string path = folder_.file("absent.obj");
  try {
    wobble::read_obj(path);
    FAIL() << "expected InputError";
  } catch (const wobble::InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": no such file", 0), 0u) << e.what();
  }
}

TEST_F(ReadObj, BadIndicesNameTheirLine) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expect_error(v + "f 1 2 0\n", "line 4: ", "'0' is not a vertex reference");
  // A vertex may come after the face that uses it, as other OBJ readers allow.
  EXPECT_EQ(read(v + "f 1 2 4\nv 1 1 1\n").faces, (Faces{{0, 1, 3}}));
  expect_error(v + "f 1 2 5\nv 1 1 1\n", "line 4: ", "index 5 refers to none of the 4 vertices");
  expect_error(v + "f 1 2 3\nf 1 2 7\n", "line 5: ", "expected 1 to 3");
  expect_error(v + "f -1 -2 -4\n", "line 4: ", "expected 1 to 3 or -1 to -3");
  expect_error(v + "vt 0 0\nf 1/1 2/2 3/1\n",
               "line 5: ", "index 2 refers to none of the 1 texture coordinates");
  expect_error(v + "f 1/1 2/1 3/1\n", "line 4: ", "the file has no texture coordinates");
  expect_error(v + "l 1 4\n", "line 4: ", "refers to none of the 3 vertices");
  expect_error(v + "l 1 -9\n", "line 4: ", "refers to none of the 3 vertices");
  expect_error(v + "f 1 2 3x\n", "line 4: ", "'3x' is not a vertex reference");
  expect_error(v + "f 1/2/3/4 2 3\n", "line 4: ", "not a vertex reference");
}

TEST_F(ReadObj, BadElementsNameTheirLine) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expect_error(v + "f 1 2 3\nf 2\n", "line 5: ", "`f` lists 1 vertices, expected at least 2");
  expect_error(v + "l 3\n", "line 4: ", "expected at least 2");
  expect_error(v + "f 1 2 1\n", "line 4: ", "uses vertex 1 twice");
  expect_error(v + "l 1 2 2\n", "line 4: ", "joins vertex 2 to itself");
}

TEST_F(ReadObj, BadCoordinatesNameTheirLine) {
  expect_error("v 0 0 0\nv 1 abc 0\n", "line 2: ", "'abc' is not a finite number");
  expect_error("v 0 0 0\nv 1 1e400 0\n", "line 2: ", "'1e400' is not a finite number");
  expect_error("\n\nv nan 0 0\n", "line 3: ", "'nan' is not a finite number");
  expect_error("v 0 0 inf\n", "line 1: ", "'inf' is not a finite number");
  expect_error("v 0 0\n", "line 1: ", "`v` has 2 coordinates, expected x y z");
  expect_error("v 0 0 0\nvt\n", "line 2: ", "expected u [v]");
}

// A `#` comment may follow any statement, not only `v`: the rest of the line is ignored. What
// is not a comment is still refused, on every kind of line.
TEST_F(ReadObj, CommentsAfterAnyStatement) {
  const wobble::ObjMesh mesh = read(
      "# a square\n"
      "v 0 0 0 # origin\nv 1 0 0\t# x\nv 1 1 0 #\nv 0 1 0 1 # with a w\n"
      "vt 0 0 # first\nvt 1 0 #second\nvt 1 1 0 # with a w\nvt 0#no space\n"
      "g roof # a group\n"
      "f 1/1 2/2 3/3 # the first triangle\n"
      "f 1/1 3/3 4/4 #\n"
      "l 2 4 # a diagonal spring\n"
      "f 1 2#touching\n");
  ASSERT_EQ(mesh.V.rows(), 4);
  EXPECT_EQ(mesh.V.row(3), Eigen::RowVector3d(0, 1, 0));
  EXPECT_EQ(mesh.faces, (Faces{{0, 1, 2}, {0, 2, 3}, {0, 1}, {1, 3}}));
  ASSERT_EQ(mesh.uv.rows(), 4);
  EXPECT_EQ(mesh.uv.row(2), Eigen::RowVector2d(1, 1));
  EXPECT_EQ(mesh.uv.row(3), Eigen::RowVector2d(0, 0));

  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expect_error(v + "f 1 2 3 note\n", "line 4: ", "'note' is not a vertex reference");
  expect_error(v + "f 1 2 3 // note\n", "line 4: ", "'//' is not a vertex reference");
  expect_error(v + "l 1 2 ; note\n", "line 4: ", "';' is not a vertex reference");
  expect_error(v + "vt 0 0 note\nf 1 2 3\n", "line 4: ", "'note' is not a finite number");
  expect_error(v + "vt 0 0 0 0\nf 1 2 3\n",
               "line 4: ", "`vt` has 4 coordinates, expected u [v] [w]");
  expect_error("v 0 0 0 junk\n", "line 1: ", "'junk' is not a finite number");
  expect_error("v 0 0 0 1 1 1 1\n", "line 1: ", "`v` has 7 coordinates");
  // A comment that swallows what a statement needs leaves it short.
  expect_error(v + "f 1 # 2 3\n", "line 4: ", "`f` lists 1 vertices");
  expect_error("v 0 0 # 0\n", "line 1: ", "`v` has 2 coordinates");
}

TEST_F(ReadObj, EmptyMeshesAreRefused) {
  const std::string path = folder_.file("mesh.obj");
  EXPECT_EQ(error(""), path + ": no vertices, expected `v x y z` lines");
  EXPECT_EQ(error("# nothing\nf\n"), path + ": line 2: `f` lists 0 vertices, expected at least 2");
  EXPECT_EQ(error("v 0 0 0\nv 1 0 0\n"),
            path + ": no faces or lines, expected `f` or `l` lines joining the vertices");
}

TEST_F(ReadObj, ByteOrderMarkBeforeTheFirstVertexKeepsThatVertexAndEveryIndex) {
  // Before, the marked first line was not read as a `v`, so the mesh lost vertex 1 and every
  // index pointed one vertex further on.
  const wobble::ObjMesh mesh = read("\xEF\xBB\xBF" + std::string(square) + "f 1 2 3\nf 1 3 4\n");
  ASSERT_EQ(mesh.V.rows(), 4);
  EXPECT_EQ(mesh.V.row(0), Eigen::RowVector3d(0, 0, 0));
  EXPECT_EQ(mesh.V.row(3), Eigen::RowVector3d(0, 1, 0));
  EXPECT_EQ(mesh.faces, (Faces{{0, 1, 2}, {0, 2, 3}}));
}

TEST_F(ReadObj, UnderflowIsReportedAsSuch) {
  expect_error(std::string(square) + "v 1e-400 0 0\nf 1 2 3\n", "line 5",
               "coordinate '1e-400' underflows");
  expect_error("v 0 0 0\nv -2e-320 0 0\nv 0 1 0\nf 1 2 3\n", "line 2", "'-2e-320' underflows");
  // The smallest normal double, and 0 written with an exponent, are numbers.
  EXPECT_EQ(read("v 2.2250738585072014e-308 0 0e-400\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").V(0, 0),
            2.2250738585072014e-308);
}

TEST_F(ReadObj, FacesWithTooManyCornersOrSpringsAreRefusedAtTheirLine) {
  const auto polygon = [](long corners) {
    std::string obj, face = "f";
    for (long c = 1; c <= corners; ++c) {
      obj += "v " + std::to_string(c) + " " + std::to_string(c * c) + " 0\n";
      face += " " + std::to_string(c);
    }
    return std::make_pair(obj, face + "\n");
  };
  const auto [largest_vertices, largest_face] = polygon(wobble::max_face_corners);
  const wobble::ObjMesh largest = read(largest_vertices + largest_face);
  EXPECT_EQ(largest.faces[0].size(), static_cast<std::size_t>(wobble::max_face_corners));

  const auto [vertices, face] = polygon(wobble::max_face_corners + 1);
  expect_error(vertices + face, "line " + std::to_string(wobble::max_face_corners + 2),
               std::to_string(wobble::max_face_corners + 1) + " corners, above Wobble's limit of " +
                   std::to_string(wobble::max_face_corners));

  // Each allowed on its own, too many together.
  const long springs_per_face = wobble::max_face_corners * (wobble::max_face_corners - 1) / 2;
  const long faces = wobble::max_face_springs / springs_per_face + 1;
  std::string many = largest_vertices;
  for (long f = 0; f < faces; ++f)
    many += largest_face;
  expect_error(
      many, "line " + std::to_string(wobble::max_face_corners + faces),
      "above Wobble's limit of " + wobble::with_thousands_separators(wobble::max_face_springs));
}

TEST_F(ReadObj, WhatIsNotARegularFileIsRefusedByName) {
  const std::string pipe = folder_.file("pipe.obj");
  ASSERT_EQ(mkfifo(pipe.c_str(), 0600), 0);
  try {
    wobble::read_obj(pipe);
    ADD_FAILURE() << "read a FIFO";
  } catch (const wobble::InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              pipe + ": is a FIFO (named pipe), not a regular file, expected an OBJ mesh");
  }
}

}  // namespace

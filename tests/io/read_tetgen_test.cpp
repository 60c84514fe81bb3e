#include "io/read_tetgen.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <string>

#include "sim/input_error.h"
#include "sim/shapes/tet_mesh.h"
#include "temporary_folder.h"

namespace {

// Writes BASE.node and BASE.ele and returns BASE.
std::string write_pair(const wobble::testing::TemporaryFolder& folder, const std::string& node,
                       const std::string& ele, const std::string& base = "mesh") {
  std::ofstream(folder.file(base + ".node")) << node;
  std::ofstream(folder.file(base + ".ele")) << ele;
  return folder.file(base);
}

// The lumped masses at density 1 add up to the total volume.
double tetgen_volume(const wobble::TetMeshFile& mesh) {
  return wobble::tet_mesh_lumped_masses(mesh.V, mesh.T, 1.0).sum();
}

TEST(ReadTetgen, OneBasedSingleTetrahedronFromAnyOfTheThreePaths) {
  wobble::testing::TemporaryFolder folder;
  const std::string base = write_pair(folder,
                                      "# points dimension attributes markers\n"
                                      "4 3 0 1\n"
                                      "1 0 0 0 1\n2 1 0 0 1   # trailing comment\n\n"
                                      "3 0 1 0 1\n4 0 0 1.25 1\n",
                                      "1 4 0\n1  1 2 3 4\n# written by hand\n");
  for (const std::string& path : {base, base + ".node", base + ".ele"}) {
    const wobble::TetMeshFile mesh = wobble::read_tetgen(path);
    ASSERT_EQ(mesh.V.rows(), 4) << path;
    ASSERT_EQ(mesh.T.rows(), 1) << path;
    EXPECT_EQ(mesh.T.row(0), Eigen::RowVector4i(0, 1, 2, 3));
    EXPECT_EQ(mesh.V.row(3), Eigen::RowVector3d(0, 0, 1.25));
  }
}

TEST(ReadTetgen, ZeroBasedCubeWithAttributesAndMarkers) {
  wobble::testing::TemporaryFolder folder;
  // The unit cube's corners (v&1, v>>1&1, v>>2&1), two attributes and a marker each; five
  // tetrahedra (four corners cut off, one in the middle) with a region attribute.
  std::string node = "8 3 2 1\n";
  for (int v = 0; v < 8; ++v) {
    node += std::to_string(v) + " " + std::to_string(v & 1) + " " + std::to_string(v >> 1 & 1) +
            " " + std::to_string(v >> 2 & 1) + " 0.5 -2 1\n";
  }
  const std::string ele =
      "5 4 1\n0 0 1 2 4 7\n1 3 1 2 7 7\n2 5 1 4 7 7\n3 6 2 4 7 7\n4 1 2 4 7 7.5\n";
  const wobble::TetMeshFile mesh = wobble::read_tetgen(write_pair(folder, node, ele));
  ASSERT_EQ(mesh.V.rows(), 8);
  ASSERT_EQ(mesh.T.rows(), 5);
  EXPECT_EQ(mesh.T.row(1), Eigen::RowVector4i(3, 1, 2, 7));
  EXPECT_EQ(mesh.V.row(6), Eigen::RowVector3d(0, 1, 1));
  EXPECT_NEAR(tetgen_volume(mesh), 1.0, 1e-15);  // the five fill the cube exactly once
}

TEST(ReadTetgen, TenNodeTetrahedronKeepsItsFourCorners) {
  wobble::testing::TemporaryFolder folder;
  // Corners 1-4, then the six edge midpoints 5-10, as `tetgen -o2` numbers them.
  const std::string node =
      "10 3\n1 0 0 0\n2 2 0 0\n3 0 2 0\n4 0 0 2\n"
      "5 1 0 0\n6 1 1 0\n7 0 1 0\n8 0 0 1\n9 1 0 1\n10 0 1 1\n";
  const std::string ele = "1 10 0\n1 1 2 3 4 6 7 5 8 9 10\n";
  const wobble::TetMeshFile mesh = wobble::read_tetgen(write_pair(folder, node, ele));
  EXPECT_EQ(mesh.V.rows(), 10);
  ASSERT_EQ(mesh.T.rows(), 1);
  EXPECT_EQ(mesh.T.row(0), Eigen::RowVector4i(0, 1, 2, 3));
}

TEST(ReadTetgen, ShippedColumnStandsOnTheGround) {
  const wobble::TetMeshFile mesh =
      wobble::read_tetgen(std::string(WOBBLE_ASSETS_DIR) + "/meshes/column.node");
  EXPECT_EQ(mesh.V.rows(), 3 * 7 * 3);
  EXPECT_EQ(mesh.T.rows(), 6 * 2 * 6 * 2);
  EXPECT_NEAR(mesh.V.col(1).minCoeff(), 0.0, 1e-12);
  EXPECT_NEAR(mesh.V.col(1).maxCoeff(), 0.6, 1e-12);
  EXPECT_NEAR(tetgen_volume(mesh), 0.2 * 0.6 * 0.2, 1e-12);
}

struct BadPair {
  const char* node;
  const char* ele;
  const char* file;      // which of the two the message must name
  const char* expected;  // after "FILE: "
};

TEST(ReadTetgen, BadFilesNameTheRightFileTheLineAndWhatWasExpected) {
  const char* const good_node = "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
  const char* const good_ele = "1 4 0\n1 1 2 3 4\n";
  const BadPair cases[] = {
      {"", good_ele, ".node", "line 1: expected the header"},
      {"# only a comment\n4 2 0 0\n", good_ele, ".node", "line 2: expected dimension 3, got 2"},
      {"0 3 0 0\n", good_ele, ".node", "line 1: expected at least one point, got 0"},
      {"4 3 0 2\n", good_ele, ".node", "line 1: expected 0 or 1 boundary markers, got 2"},
      {"4 3 0 0\n2 0 0 0\n", good_ele, ".node",
       "line 2: expected the first point to be numbered 0 or 1, got 2"},
      {"4 3 0 0\n1 0 0 0\n3 1 0 0\n", good_ele, ".node", "line 3: expected point number 2 (points"},
      {"4 3 0 0\n1 0 0 0\n2 1 0 x\n", good_ele, ".node",
       "line 3: expected a coordinate (a finite number), got 'x'"},
      {"4 3 0 0\n1 0 0 0\n2 1 0 inf\n", good_ele, ".node",
       "line 3: expected a coordinate (a finite number), got 'inf'"},
      {"4 3 0 1\n1 0 0 0\n", good_ele, ".node",
       "line 2: expected 5 numbers (index, x, y, z, attributes, marker), got 4"},
      {"4 3 0 0\n1 0 0 0\n2 1 0 0\n\n", good_ele, ".node",
       "line 4: expected 4 points, found 2, but the file ends"},
      {"2000000000 3\n1 0 0 0\n", good_ele, ".node",
       "line 2: expected 2000000000 points, found 1, but the file ends"},
      {good_node, "0 4 0\n", ".ele", "line 1: expected at least one tetrahedron, got 0"},
      {good_node, "1 8 0\n", ".ele", "line 1: expected 4 or 10 nodes per tetrahedron, got 8"},
      {good_node, "2 4 0\n1 1 2 3 4\n", ".ele",
       "line 2: expected 2 tetrahedra, found 1, but the file ends"},
      {good_node, "1 4 0\n1 0 1 2 3\n", ".ele",
       "line 2: expected point indices from 1 to 4, got 0"},
      {good_node, "1 4 0\n# comment\n1 1 2 3 5\n", ".ele",
       "line 3: expected point indices from 1 to 4, got 5"},
      {good_node, "1 4 1\n1 1 2 3 4\n", ".ele",
       "line 2: expected 6 numbers (index, 4 nodes, attributes), got 5"},
      {good_node, "1 4 0\n1 1 2 3 3\n", ".ele", "line 2: expected a tetrahedron with volume"},
      {good_node, "1 4 0\n1 1 2 3 four\n", ".ele",
       "line 2: expected a point index (a whole number), got 'four'"},
  };
  wobble::testing::TemporaryFolder folder;
  for (const BadPair& bad : cases) {
    const std::string base = write_pair(folder, bad.node, bad.ele);
    const std::string file = base + bad.file;
    try {
      wobble::read_tetgen(base + ".ele");
      ADD_FAILURE() << "accepted: " << bad.node << "\n" << bad.ele;
    } catch (const wobble::InputError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind(file + ": " + bad.expected, 0), 0u)
          << "got: " << message << "\nexpected: " << file << ": " << bad.expected;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
}

TEST(ReadTetgen, MissingEleIsNamed) {
  wobble::testing::TemporaryFolder folder;
  std::ofstream(folder.file("lonely.node")) << "4 3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
  try {
    wobble::read_tetgen(folder.file("lonely.node"));
    ADD_FAILURE() << "read a .node without its .ele";
  } catch (const wobble::InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(folder.file("lonely.ele") + ": no such file", 0), 0u)
        << error.what();
  }
}

TEST(ReadTetgen, ByteOrderMarksAreSkippedInBothFiles) {
  wobble::testing::TemporaryFolder folder;
  const std::string base = write_pair(folder,
                                      "\xEF\xBB\xBF"
                                      "4 3 0 0\n1 0 0 0\n2 3 0 0\n3 0 1 0\n4 0 0 1\n",
                                      "\xEF\xBB\xBF"
                                      "1 4 0\n1 4 3 2 1\n");
  const wobble::TetMeshFile mesh = wobble::read_tetgen(base + ".ele");
  ASSERT_EQ(mesh.V.rows(), 4);
  EXPECT_EQ(mesh.V.row(1), Eigen::RowVector3d(3, 0, 0));
  ASSERT_EQ(mesh.T.rows(), 1);
  EXPECT_EQ(mesh.T.row(0), Eigen::RowVector4i(3, 2, 1, 0));
}

TEST(ReadTetgen, UnderflowIsReportedAsSuchWithItsLine) {
  wobble::testing::TemporaryFolder folder;
  const std::string base = write_pair(folder, "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1e-400\n",
                                      "1 4 0\n1 1 2 3 4\n");
  try {
    wobble::read_tetgen(base);
    ADD_FAILURE() << "read 1e-400";
  } catch (const wobble::InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(base + ".node: line 5: ", 0), 0u) << error.what();
    EXPECT_NE(std::string(error.what()).find("'1e-400' underflows"), std::string::npos);
  }
}

TEST(ReadTetgen, NodeBesideANamedEleMustBeARegularFile) {
  wobble::testing::TemporaryFolder folder;
  std::ofstream(folder.file("pipe.ele")) << "1 4 0\n1 1 2 3 4\n";
  ASSERT_EQ(mkfifo(folder.file("pipe.node").c_str(), 0600), 0);
  std::ofstream(folder.file("dir.ele")) << "1 4 0\n1 1 2 3 4\n";
  std::filesystem::create_directory(folder.file("dir.node"));
  const auto message = [](const std::string& path) {
    try {
      wobble::read_tetgen(path);
    } catch (const wobble::InputError& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  EXPECT_EQ(message(folder.file("pipe.ele")),
            folder.file("pipe.node") +
                ": is a FIFO (named pipe), not a regular file, expected a TetGen .node file");
  EXPECT_EQ(message(folder.file("dir.ele")),
            folder.file("dir.node") + ": is a folder, expected a TetGen .node file");
}

}  // namespace

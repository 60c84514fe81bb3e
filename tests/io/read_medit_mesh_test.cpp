#include "io/read_medit_mesh.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <string>

#include "sim/input_error.h"
#include "sim/shapes/tet_mesh.h"
#include "temporary_folder.h"

namespace {

std::string write_file(const wobble::testing::TemporaryFolder& folder, const std::string& name,
                       const std::string& text) {
  const std::string path = folder.file(name);
  std::ofstream(path) << text;
  return path;
}

// The lumped masses at density 1 add up to the total volume.
double medit_volume(const wobble::TetMeshFile& mesh) {
  return wobble::tet_mesh_lumped_masses(mesh.V, mesh.T, 1.0).sum();
}

// The unit cube's corners (v&1, v>>1&1, v>>2&1) as MEDIT rows, then its split into five
// tetrahedra (four corners cut off, one in the middle), 1-based.
const char* const kCubeVertices =
    "8\n0 0 0 0\n1 0 0 0\n0 1 0 0\n1 1 0 0\n0 0 1 0\n1 0 1 0\n0 1 1 0\n1 1 1 0\n";
const char* const kCubeTetrahedra = "5\n1 2 3 5 1\n4 2 3 8 1\n6 2 5 8 1\n7 3 5 8 1\n2 3 5 8 1\n";

TEST(ReadMeditMesh, SingleTetrahedronBecomesZeroBased) {
  wobble::testing::TemporaryFolder folder;
  const std::string path = write_file(folder, "one.mesh",
                                      "MeshVersionFormatted 2\n"
                                      "Dimension 3\n"
                                      "# a comment line\n"
                                      "Vertices\n4\n"
                                      "0 0 0 7\n1.5 0 0 7  # comment after a row\n"
                                      "0 2e0 0 7\n0 0 -3 7\n"
                                      "Tetrahedra\n1\n1 2 3 4 0\n"
                                      "End\n");
  const wobble::TetMeshFile mesh = wobble::read_medit_mesh(path);
  ASSERT_EQ(mesh.V.rows(), 4);
  ASSERT_EQ(mesh.T.rows(), 1);
  EXPECT_EQ(mesh.V.row(1), Eigen::RowVector3d(1.5, 0, 0));
  EXPECT_EQ(mesh.V.row(3), Eigen::RowVector3d(0, 0, -3));
  EXPECT_EQ(mesh.T.row(0), Eigen::RowVector4i(0, 1, 2, 3));
}

TEST(ReadMeditMesh, KeywordsInAnyOrderRowsAcrossLinesAndOtherSectionsSkipped) {
  wobble::testing::TemporaryFolder folder;
  const std::string path =
      write_file(folder, "cube.mesh",
                 std::string("tetrahedra ") + kCubeTetrahedra +
                     "Triangles 2\n1 2 3 0\n2 4 3\n0\n"  // rows need not follow lines
                     "Edges 1 1 2 0 Corners 2 1 8\n" +
                     "Vertices " + kCubeVertices +
                     "MeshVersionFormatted 1 Dimension 3\n");  // no End: the file's end will do
  const wobble::TetMeshFile mesh = wobble::read_medit_mesh(path);
  EXPECT_EQ(mesh.V.rows(), 8);
  ASSERT_EQ(mesh.T.rows(), 5);
  EXPECT_EQ(mesh.T.row(1), Eigen::RowVector4i(3, 1, 2, 7));
  EXPECT_EQ(mesh.V.row(7), Eigen::RowVector3d(1, 1, 1));
  EXPECT_NEAR(medit_volume(mesh), 1.0, 1e-15);  // the five fill the cube exactly once
}

TEST(ReadMeditMesh, ShippedJellyCubeIsAFortyCentimetreCubeOnTheGround) {
  const wobble::TetMeshFile mesh =
      wobble::read_medit_mesh(std::string(WOBBLE_ASSETS_DIR) + "/meshes/jelly_cube.mesh");
  EXPECT_EQ(mesh.V.rows(), 5 * 5 * 5);
  EXPECT_EQ(mesh.T.rows(), 6 * 4 * 4 * 4);
  EXPECT_NEAR(mesh.V.col(1).minCoeff(), 0.0, 1e-12);
  EXPECT_NEAR(mesh.V.col(1).maxCoeff(), 0.4, 1e-12);
  EXPECT_NEAR(medit_volume(mesh), 0.4 * 0.4 * 0.4, 1e-12);
}

struct BadFile {
  const char* text;
  const char* expected;  // after "PATH: "
};

TEST(ReadMeditMesh, BadFilesNameTheFileTheLineAndWhatWasExpected) {
  const std::string four_vertices = "Vertices 4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n";
  const BadFile cases[] = {
      {"Vertices 1\n0 0 zero 0\n", "line 2: expected a coordinate in Vertices row 1, got 'zero'"},
      {"Vertices 1\n0 nan 0 0\n", "line 2: expected a coordinate in Vertices row 1 (finite)"},
      {"Vertices 3\n0 0 0 0\n1 0 0 0\n0 1", "line 4: expected a coordinate in Vertices row 3, but"},
      {"Vertices 2000000\n0 0 0 0\n", "line 3: expected a coordinate in Vertices row 2, but"},
      // A few bytes asking for billions are refused before any row is read.
      {"Vertices 2000000000\n0 0 0 0\n",
       "line 1: expected at most 10,000,000 Vertices (Wobble's limit), got 2000000000"},
      {"Vertices 10000001\n", "line 1: expected at most 10,000,000 Vertices"},
      {"Tetrahedra 60000001\n",
       "line 1: expected at most 60,000,000 Tetrahedra (Wobble's limit), got 60000001"},
      {"Vertices -2\n", "line 1: expected a non-negative number of Vertices, got -2"},
      {"Dimension 2\n", "line 1: expected Dimension 3, got 2"},
      {"Vertices 0\nSolAtVertices 1\n", "line 2: expected a MEDIT keyword"},
      {"Vertices 0\nTetrahedra 0\nEnd\n", "line 3: expected a Tetrahedra section with at least"},
      {"Tetrahedra 1\n1 2 3 4 0\n", "line 3: expected a Vertices section"},
      {"Vertices 0 Vertices 0", "line 1: expected one Vertices section, found a second"},
      {"Tetrahedra 1\n1 2 3 4.5 0\n",
       "line 2: expected a vertex index in Tetrahedra row 1 (a whole"},
      {"Tetrahedra 2\n1 2 3 4 0\n\n0 2 3 4 0\n",
       "line 4: expected vertex indices from 1 to 4 in Tetrahedra row 2, got 0"},
      {"Tetrahedra 1\n\n1 2 3 5 0\n",
       "line 3: expected vertex indices from 1 to 4 in Tetrahedra row"},
      {"Tetrahedra 1\n1 2 3 3 0\n",
       "line 2: expected a tetrahedron with volume in Tetrahedra row 1"},
  };
  wobble::testing::TemporaryFolder folder;
  for (const BadFile& bad : cases) {
    std::string text = bad.text;
    // Cases about tetrahedra get four vertices after them, so only the tetrahedra are wrong.
    if (text.rfind("Tetrahedra", 0) == 0 && text.find("Vertices") == std::string::npos &&
        std::string(bad.expected).find("Vertices section") == std::string::npos)
      text += four_vertices;
    const std::string path = write_file(folder, "bad.mesh", text);
    try {
      wobble::read_medit_mesh(path);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const wobble::InputError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind(path + ": " + bad.expected, 0), 0u)
          << "got: " << message << "\nexpected: " << bad.expected;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
}

TEST(ReadMeditMesh, MissingFileIsAnInputErrorNamingIt) {
  wobble::testing::TemporaryFolder folder;
  const std::string path = folder.file("absent.mesh");
  try {
    wobble::read_medit_mesh(path);
    ADD_FAILURE() << "read a missing file";
  } catch (const wobble::InputError& error) {
    EXPECT_EQ(
        std::string(error.what()).rfind(path + ": no such file, expected a MEDIT .mesh file", 0),
        0u)
        << error.what();
  }
}

TEST(ReadMeditMesh, ByteOrderMarkBeforeTheFirstKeywordIsSkipped) {
  wobble::testing::TemporaryFolder folder;
  const std::string path =
      write_file(folder, "bom.mesh",
                 "\xEF\xBB\xBFMeshVersionFormatted 1\nDimension 3\nVertices\n4\n"
                 "0 0 0 1\n2 0 0 1\n0 1 0 1\n0 0 1 1\nTetrahedra\n1\n1 2 3 4 1\nEnd\n");
  const wobble::TetMeshFile mesh = wobble::read_medit_mesh(path);
  ASSERT_EQ(mesh.V.rows(), 4);
  EXPECT_EQ(mesh.V.row(1), Eigen::RowVector3d(2, 0, 0));
  ASSERT_EQ(mesh.T.rows(), 1);
  EXPECT_EQ(mesh.T.row(0), Eigen::RowVector4i(0, 1, 2, 3));
}

TEST(ReadMeditMesh, UnderflowIsReportedAsSuchWithItsLine) {
  wobble::testing::TemporaryFolder folder;
  const std::string path = write_file(folder, "tiny.mesh",
                                      "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n"
                                      "0 0 0 1\n1 0 0 1\n0 1e-400 0 1\n0 0 1 1\n");
  try {
    wobble::read_medit_mesh(path);
    ADD_FAILURE() << "read 1e-400";
  } catch (const wobble::InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(path + ": line 7: ", 0), 0u) << error.what();
    EXPECT_NE(std::string(error.what()).find("'1e-400' underflows"), std::string::npos)
        << error.what();
  }
}

TEST(ReadMeditMesh, DeviceIsRefusedWithoutReadingIt) {
  wobble::testing::TemporaryFolder folder;
  std::filesystem::create_symlink("/dev/zero", folder.file("zero.mesh"));
  try {
    wobble::read_medit_mesh(folder.file("zero.mesh"));
    ADD_FAILURE() << "read /dev/zero";
  } catch (const wobble::InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              folder.file("zero.mesh") +
                  ": is a character device, not a regular file, expected a MEDIT .mesh file");
  }
}

}  // namespace

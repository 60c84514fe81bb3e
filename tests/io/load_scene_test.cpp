#include "io/load_scene.h"

#include <gtest/gtest.h>

#include <fstream>

#include "io/write_obj.h"
#include "sim/input_error.h"
#include "sim/shapes/builtin_scenes.h"
#include "temporary_folder.h"

namespace {

using wobble::testing::TemporaryFolder;

std::string load_error(const std::string& source, bool fill = false) {
  try {
    wobble::load_scene(source, fill);
  } catch (const wobble::InputError& error) {
    return error.what();
  }
  return "(no error)";
}

// A unit cube's surface, 8 vertices and 12 triangles facing out, standing on y = 0.
void write_cube(const std::string& path) {
  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                         "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                         "f 1 4 3\nf 1 3 2\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n"
                         "f 4 8 7\nf 4 7 3\nf 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 7 6\n";
}

TEST(LoadScene, BuiltInNamesGiveTheBuiltInScenes) {
  const wobble::Scene cloth = wobble::load_scene("cloth");
  EXPECT_EQ(cloth.network.V, wobble::make_builtin_scene("cloth").network.V);
  EXPECT_NE(load_error("clothes").find("no such scene file or built-in scene (built-in: cloth, "
                                       "jelly)"),
            std::string::npos);
}

TEST(LoadScene, BareObjIsPinnedAtItsTopAndSaysSo) {
  TemporaryFolder folder;
  // A 1 m × 1 m vertical quad made of two triangles, plus a vertex below on a line.
  std::ofstream(folder.file("sheet.obj")) << "v 0 2 0\nv 1 2 0\nv 1 1 0\nv 0 1 0\n"
                                             "f 1 4 3\nf 1 3 2\n";
  const wobble::Scene scene = wobble::load_scene(folder.file("sheet.obj"));
  EXPECT_EQ(scene.name, "sheet");
  EXPECT_EQ(scene.pins, (std::vector<int>{0, 1}));
  ASSERT_EQ(scene.notes.size(), 1u);
  EXPECT_NE(scene.notes[0].find("pinned the 2 top-most vertices"), std::string::npos);
  EXPECT_EQ(scene.network.E.rows(), 5);                   // 4 sides and the shared diagonal
  EXPECT_NEAR(scene.network.m.sum(), 0.25 * 1.0, 1e-12);  // 0.25 kg/m² over 1 m²
  EXPECT_EQ(scene.params.k, 400.0);
}

TEST(LoadScene, ClosedObjFilledIsAJellyOnItsBase) {
  TemporaryFolder folder;
  write_cube(folder.file("cube.obj"));
  const wobble::Scene scene = wobble::load_scene(folder.file("cube.obj"), /*fill=*/true);
  EXPECT_GT(scene.network.V.rows(), 8);
  EXPECT_NEAR(scene.network.m.sum(), 200.0 * 1.0, 200.0 * 0.05);  // 200 kg/m³ × about 1 m³
  EXPECT_FALSE(scene.pins.empty());
  for (int i : scene.pins)
    EXPECT_NEAR(scene.network.V(i, 1), 0.0, 1e-9);
  EXPECT_NE(load_error(folder.file("cube.obj") + ".none"), "(no error)");
  EXPECT_NE(load_error("cloth", true).find("--fill"), std::string::npos);
}

TEST(LoadScene, ExportedObjLoadsAgain) {
  TemporaryFolder folder;
  const wobble::Scene cloth = wobble::make_builtin_scene("cloth");
  wobble::write_obj(folder.file("out.obj"), cloth.network.V, cloth.network.F, cloth.network.E);
  const wobble::Scene again = wobble::load_scene(folder.file("out.obj"));
  // The OBJ holds shortest round-trip decimals, which strtod reads back exactly.
  EXPECT_EQ(again.network.V, cloth.network.V);
  EXPECT_EQ(again.network.F, cloth.network.F);
}

TEST(LoadScene, UnknownFilesAreRefusedByName) {
  TemporaryFolder folder;
  std::ofstream(folder.file("notes.txt")) << "hello";
  const std::string message = load_error(folder.file("notes.txt"));
  EXPECT_NE(message.find("notes.txt: unknown kind of file"), std::string::npos) << message;
}

// Found by fuzz_obj: a surface whose faces all have zero area gave every vertex the mean mass,
// 0, and the error from the spring network's check named no file.
TEST(LoadScene, ObjWhoseFacesHaveNoAreaIsRefusedByName) {
  TemporaryFolder folder;
  const std::string path = folder.file("line.obj");
  std::ofstream(path) << "f 1 2 3\nv 0 0 8\nv 0 0 5\nv 0 0 5\n";
  EXPECT_EQ(load_error(path), path + ": every face has zero area, so no vertex gets a mass from " +
                                  "its area; expected faces whose corners are not all on one line");
}

// Zero-area faces are wrong only where the masses come from areas: a scene that gives every
// vertex its mass (as a saved scene does) loads, and one that asks for a density or a total
// mass, or leaves the masses to the default, is refused naming the mesh and the way out.
TEST(LoadScene, ZeroAreaFacesNeedMassesGivenVertexByVertex) {
  TemporaryFolder folder;
  std::ofstream(folder.file("line.obj")) << "v 0 0 0\nv 0 0 1\nv 0 0 2\nf 1 2 3\n";
  const std::string scene = folder.file("scene.json");
  std::ofstream(scene) << R"({"mesh": {"file": "line.obj"}, "pins": [0],
                              "material": {"vertex_masses": [0.5, 0.25, 2]}})";
  const wobble::Scene loaded = wobble::load_scene(scene);
  EXPECT_EQ(loaded.network.m, Eigen::Vector3d(0.5, 0.25, 2));
  EXPECT_EQ(loaded.network.F.rows(), 1);
  EXPECT_TRUE(loaded.notes.empty());

  const std::string refusal = scene + ": mesh.file '" + folder.file("line.obj") +
                              "': every face has zero area, so no vertex gets a mass from its " +
                              "area; expected faces whose corners are not all on one line, or " +
                              "material.vertex_masses giving every vertex its mass";
  for (const std::string material :
       {"", R"(, "material": {"density": 2})", R"(, "material": {"mass": 1, "k": 10})"}) {
    std::ofstream(scene, std::ios::trunc) << R"({"mesh": {"file": "line.obj"})" + material + "}";
    EXPECT_EQ(load_error(scene), refusal) << material;
  }
}

}  // namespace

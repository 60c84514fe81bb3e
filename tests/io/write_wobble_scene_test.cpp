#include "io/write_wobble_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "io/load_scene.h"
#include "saved_scene_checks.h"
#include "shipped_scenes.h"
#include "sim/input_error.h"
#include "sim/settings/setting_registry.h"
#include "temporary_folder.h"

namespace wobble {
namespace {

using testing::expect_same_scene;
using testing::expect_same_steps;
using testing::TemporaryFolder;

std::string file_name_for(const std::string& scene) {
  return std::filesystem::path(scene).stem().string() + ".json";
}

// Every scene Wobble ships, saved and opened again, is the same scene and steps the same.
TEST(WriteWobbleScene, EveryShippedSceneRoundTripsBitForBit) {
  TemporaryFolder folder;
  for (const std::string& name : testing::shipped_scenes(WOBBLE_ASSETS_DIR)) {
    SCOPED_TRACE(name);
    const Scene opened = load_scene(name);
    const std::string saved_path = folder.file(file_name_for(name));
    write_wobble_scene(saved_path, opened);
    const Scene saved = load_scene(saved_path);
    expect_same_scene(opened, saved);
    expect_same_steps(opened, saved, 20);
  }
}

// The mesh file keeps E's order and direction even where they are not what face_springs would
// build from the triangles (which sorts the pairs), and keeps repeated springs.
TEST(WriteWobbleScene, KeepsSpringOrderDirectionAndRepeats) {
  TemporaryFolder folder;
  Scene scene = load_scene("cloth");
  const Eigen::Index n = scene.network.E.rows();
  Eigen::MatrixXi E(n + 1, 2);
  for (Eigen::Index e = 0; e < n; ++e)
    E.row(e) << scene.network.E(n - 1 - e, 1), scene.network.E(n - 1 - e, 0);
  E.row(n) = E.row(0);
  scene.network.E = E;
  write_wobble_scene(folder.file("reversed.json"), scene);
  const Scene saved = load_scene(folder.file("reversed.json"));
  EXPECT_TRUE(testing::same_matrix(scene.network.E, saved.network.E));
}

// Masses that no density or total mass would spread (here one vertex made 3 times heavier) and
// a vertical sway survive exactly.
TEST(WriteWobbleScene, KeepsEveryMassAndTheSway) {
  TemporaryFolder folder;
  Scene scene = load_scene("cloth");
  scene.network.m(5) *= 3.0;
  const Eigen::MatrixXd& V = scene.network.V;
  const double low = V.col(1).minCoeff();
  const double span = std::max(V.col(1).maxCoeff() - low, 1e-12);
  scene.initial_velocity = Eigen::MatrixXd::Zero(V.rows(), 3);
  scene.initial_velocity.col(0) = 0.7 * (V.col(1).array() - low) / span;
  write_wobble_scene(folder.file("heavy.json"), scene);
  const Scene saved = load_scene(folder.file("heavy.json"));
  EXPECT_TRUE(testing::same_matrix(scene.network.m, saved.network.m));
  EXPECT_TRUE(testing::same_matrix(scene.initial_velocity, saved.initial_velocity));
}

TEST(WriteWobbleScene, RefusesAVelocityTheFormatCannotStateAndWritesNothing) {
  TemporaryFolder folder;
  Scene scene = load_scene("cloth");
  scene.initial_velocity = Eigen::MatrixXd::Zero(scene.network.V.rows(), 3);
  scene.initial_velocity(3, 2) = 1.0;
  const std::string path = folder.file("moving.json");
  try {
    write_wobble_scene(path, scene);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("initial velocity"), std::string::npos);
  }
  EXPECT_TRUE(folder.entries().empty());
}

TEST(WriteWobbleScene, IntoAMissingFolderFailsNamingThePathAndLeavesNothing) {
  TemporaryFolder folder;
  const std::string path = folder.file("missing/saved.json");
  try {
    write_wobble_scene(path, load_scene("jelly"));
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
  }
  EXPECT_TRUE(folder.entries().empty());
}

TEST(WriteWobbleScene, RefusesAJsonPathThatIsItsOwnMeshFile) {
  TemporaryFolder folder;
  EXPECT_THROW(write_wobble_scene(folder.file("saved.obj"), load_scene("jelly")), InputError);
  EXPECT_TRUE(folder.entries().empty());
}

// A texture inside the saved file's folder is named relative to it, so the folder can move.
TEST(WriteWobbleScene, NamesATextureBesideTheSavedFileRelatively) {
  TemporaryFolder folder;
  Scene scene = load_scene(std::string(WOBBLE_ASSETS_DIR) + "/flag.json");
  ASSERT_FALSE(scene.look.texture.empty());
  std::filesystem::create_directory(folder.path() / "textures");
  const std::filesystem::path copy = folder.path() / "textures" / "flag.png";
  std::filesystem::copy_file(scene.look.texture, copy);
  scene.look.texture = copy.string();
  const nlohmann::json object = wobble_scene_json(scene, "flag.obj", "textures/flag.png");
  EXPECT_EQ(object["appearance"]["texture"], "textures/flag.png");
  write_wobble_scene(folder.file("flag.json"), scene);
  const nlohmann::json written = nlohmann::json::parse(std::ifstream(folder.file("flag.json")));
  EXPECT_EQ(written["appearance"]["texture"], "textures/flag.png");
  const Scene saved = load_scene(folder.file("flag.json"));
  EXPECT_TRUE(std::filesystem::equivalent(saved.look.texture, copy));
}

// Plane normals are unit vectors after loading; reading one back must not divide it by a length
// that rounds away from 1 (about a third of unit vectors would move by an ulp).
TEST(WriteWobbleScene, KeepsPlaneNormalsBitForBit) {
  TemporaryFolder folder;
  Scene scene = load_scene("jelly");
  for (int c = 0; c < 40; ++c) {
    Collider plane;
    plane.type = ColliderType::plane;
    plane.center = Eigen::Vector3d(0.0, -1.0 - c, 0.0);
    plane.normal = Eigen::Vector3d(std::sin(c + 0.5), 1.0 + 0.1 * c, std::cos(3.0 * c));
    plane.normal.normalize();
    scene.params.contact.colliders.push_back(plane);
  }
  write_wobble_scene(folder.file("planes.json"), scene);
  const Scene saved = load_scene(folder.file("planes.json"));
  testing::expect_same_params(scene.params, saved.params);
}

// Another solver than the default is written and read back; the default writes no key, so that
// scenes saved before there was a choice read and write the same.
TEST(WriteWobbleScene, WritesTheSolverOnlyWhenNotTheDefault) {
  TemporaryFolder folder;
  Scene scene = load_scene("cloth");
  ASSERT_EQ(scene.params.solver, "local-global");
  EXPECT_FALSE(wobble_scene_json(scene, "default.obj", "")["simulation"].contains("solver"));
  scene.params.solver = "lbfgs";
  const nlohmann::json object = wobble_scene_json(scene, "lbfgs.obj", "");
  EXPECT_EQ(object["simulation"]["solver"], "lbfgs");
  write_wobble_scene(folder.file("lbfgs.json"), scene);
  const Scene saved = load_scene(folder.file("lbfgs.json"));
  EXPECT_EQ(saved.params.solver, "lbfgs");
  expect_same_scene(scene, saved);
  expect_same_steps(scene, saved, 5);
}

// Self-collision on survives with its thickness; off, the file has no key (its presence would
// turn it on).
TEST(WriteWobbleScene, KeepsSelfCollisionOnlyWhenOn) {
  TemporaryFolder folder;
  Scene scene = load_scene("cloth");
  ASSERT_FALSE(scene.params.self_collision.on);
  EXPECT_FALSE(wobble_scene_json(scene, "off.obj", "").contains("self_collision"));
  scene.params.self_collision.on = true;
  scene.params.self_collision.thickness = 0.0037;
  const nlohmann::json object = wobble_scene_json(scene, "on.obj", "");
  ASSERT_TRUE(object.contains("self_collision"));
  EXPECT_EQ(object["self_collision"]["thickness"], 0.0037);
  write_wobble_scene(folder.file("on.json"), scene);
  const Scene saved = load_scene(folder.file("on.json"));
  EXPECT_TRUE(saved.params.self_collision.on);
  EXPECT_EQ(saved.params.self_collision.thickness, 0.0037);
  expect_same_scene(scene, saved);
}

// A stiffness alone in a file turns the volume term on (it implies the switch), so a jelly saved
// with the term off and its own stiffness says "volume": false, and reads back off; a file
// that gives both keeps both.
TEST(WriteWobbleScene, KeepsTheVolumeTermOffBesideItsStiffness) {
  TemporaryFolder folder;
  std::ofstream(folder.file("stiffness.json"))
      << R"({"mesh": {"generator": "jelly", "resolution": 2},
             "simulation": {"volume_stiffness": 5000}})";
  const Scene stiffness_alone = load_scene(folder.file("stiffness.json"));
  EXPECT_EQ(setting_value(stiffness_alone.params, "volume"), 1.0);
  EXPECT_EQ(setting_value(stiffness_alone.params, "volume-stiffness"), 5000.0);
  std::ofstream(folder.file("both.json")) << R"({"mesh": {"generator": "jelly", "resolution": 2},
             "simulation": {"volume": false, "volume_stiffness": 5000}})";
  const Scene both = load_scene(folder.file("both.json"));
  EXPECT_EQ(setting_value(both.params, "volume"), 0.0);

  Scene scene = load_scene("jelly");
  set_setting_value(scene.params, "volume", 0.0);
  set_setting_value(scene.params, "volume-stiffness", 5000.0);
  const nlohmann::json object = wobble_scene_json(scene, "off.obj", "");
  EXPECT_EQ(object["simulation"]["volume"], false);
  write_wobble_scene(folder.file("off.json"), scene);
  const Scene saved = load_scene(folder.file("off.json"));
  EXPECT_EQ(setting_value(saved.params, "volume"), 0.0);
  EXPECT_EQ(setting_value(saved.params, "volume-stiffness"), 5000.0);
  expect_same_scene(scene, saved);
}

}  // namespace
}  // namespace wobble

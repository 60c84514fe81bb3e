#include "app/viewer/scene_save.h"
#include <filesystem>

#include <gtest/gtest.h>

#include <algorithm>

#include "../../io/saved_scene_checks.h"
#include "../../io/temporary_folder.h"
#include "app/viewer/window_saves.h"
#include "io/load_scene.h"
#include "sim/contact/collider_contact_term.h"
#include "sim/input_error.h"

namespace wobble {
namespace {

using testing::same_matrix;
using testing::TemporaryFolder;

// The built-in cloth with one collider of every type, as a scene that the user then changes.
Scene cloth_with_colliders() {
  Scene scene = load_scene("cloth");
  std::vector<Collider>& colliders = scene.params.contact.colliders;
  Collider ground;
  ground.height = -0.5;
  Collider sphere;
  sphere.type = ColliderType::sphere;
  sphere.center = Eigen::Vector3d(0.1, 0.6, -0.2);
  sphere.radius = 0.3;
  sphere.friction = 0.7;
  Collider box;
  box.type = ColliderType::box;
  box.center = Eigen::Vector3d(-0.3, 0.2, 0.1);
  box.size = Eigen::Vector3d(0.2, 0.3, 0.4);
  Collider capsule;
  capsule.type = ColliderType::capsule;
  capsule.from = Eigen::Vector3d(-0.5, 0.4, 0.0);
  capsule.to = Eigen::Vector3d(0.5, 0.45, 0.1);
  capsule.radius = 0.05;
  Collider plane;
  plane.type = ColliderType::plane;
  plane.center = Eigen::Vector3d(0.0, -0.3, 0.0);
  plane.normal = Eigen::Vector3d(0.3, 1.0, 0.2);
  colliders = {ground, sphere, box, capsule, plane};
  return scene;
}

TEST(SaveCurrentScene, KeepsEverySettingChangedSinceTheSceneOpened) {
  TemporaryFolder folder;
  const Scene opened = cloth_with_colliders();
  Simulation simulation(opened.network, opened.pins, opened.params, opened.initial_velocity);
  ASSERT_FALSE(opened.pins.empty());
  simulation.apply(wobble::with_setting(simulation.params(), "k", 777.5));
  simulation.apply(wobble::with_setting(simulation.params(), "dt", 0.01));
  simulation.apply(wobble::with_setting(simulation.params(), "iterations", 17.0));
  simulation.apply(wobble::with_setting(simulation.params(), "chebyshev", true));
  simulation.apply(wobble::with_setting(simulation.params(), "solver", std::string("lbfgs")));
  simulation.apply(wobble::with_setting(
      wobble::with_setting(simulation.params(), "gravity", Eigen::Vector3d(0.5, -4.25, 0.125)),
      "gravity-model", std::string("acceleration")));
  simulation.apply(wobble::with_setting(simulation.params(), "damping", 0.3));
  simulation.apply([&] {
    wobble::SimulationParams changed = simulation.params();
    changed.wind = WindParams::default_breeze();
    return changed;
  }());
  simulation.apply(wobble::with_setting(simulation.params(), "friction", 0.45));
  simulation.unpin(opened.pins.front());
  simulation.pin(7);
  simulation.set_pin_target(7, Eigen::Vector3d(3.0, 3.0, 3.0));
  simulation.term<wobble::ColliderContactTerm>()->translate(1, Eigen::Vector3d(0.1, -0.2, 0.3));
  simulation.term<wobble::ColliderContactTerm>()->translate(4, Eigen::Vector3d(0.0, 0.05, 0.0));
  for (int step = 0; step < 5; ++step)
    simulation.step();
  const std::pair<Eigen::Vector3d, Eigen::Vector3d> camera(Eigen::Vector3d(1.0, 2.0, 3.0),
                                                           Eigen::Vector3d(0.0, 0.5, 0.0));

  const std::string path = unused_file_name(folder.path().string(), "saved", ".json");
  save_current_scene(path, opened, simulation, camera);
  const Scene saved = load_scene(path);

  EXPECT_EQ(saved.params.k, 777.5);
  EXPECT_EQ(saved.params.dt, 0.01);
  EXPECT_EQ(saved.params.iterations, 17);
  EXPECT_TRUE(saved.params.chebyshev);
  EXPECT_EQ(saved.params.solver, "lbfgs");
  EXPECT_TRUE(same_matrix(saved.params.gravity, Eigen::Vector3d(0.5, -4.25, 0.125)));
  EXPECT_EQ(saved.params.damping, 0.3);
  EXPECT_TRUE(saved.params.wind.on);
  EXPECT_TRUE(same_matrix(saved.params.wind.velocity, WindParams::default_breeze().velocity));
  EXPECT_EQ(saved.params.contact.friction, 0.45);
  EXPECT_EQ(saved.pins, simulation.pinned_vertices());
  EXPECT_EQ(std::count(saved.pins.begin(), saved.pins.end(), opened.pins.front()), 0);
  EXPECT_EQ(std::count(saved.pins.begin(), saved.pins.end(), 7), 1);
  ASSERT_EQ(saved.params.contact.colliders.size(), 5u);
  EXPECT_TRUE(same_matrix(saved.params.contact.colliders[1].center,
                          Eigen::Vector3d(0.1, 0.6, -0.2) + Eigen::Vector3d(0.1, -0.2, 0.3)));
  EXPECT_EQ(saved.look.camera_position, camera.first);
  EXPECT_EQ(saved.look.camera_target, camera.second);

  // Everything else, field by field, against what was meant to be saved, and the stepping.
  Scene meant = scene_to_save(opened, simulation, camera);
  // Saved, it is a scene of its own, named as its file (the picker lists it so).
  EXPECT_EQ(saved.name, std::filesystem::path(path).stem().string());
  EXPECT_NE(saved.name, opened.name);
  meant.name = saved.name;
  testing::expect_same_scene(meant, saved);
  testing::expect_same_steps(meant, saved, 20);
}

TEST(SaveCurrentScene, WithoutACameraKeepsTheOpenedOne) {
  TemporaryFolder folder;
  Scene opened = load_scene("jelly");
  opened.look.camera_position = Eigen::Vector3d(2.0, 1.0, 2.0);
  opened.look.camera_target = Eigen::Vector3d(0.0, 0.25, 0.0);
  Simulation simulation(opened.network, opened.pins, opened.params, opened.initial_velocity);
  save_current_scene(folder.file("jelly.json"), opened, simulation, std::nullopt);
  const Scene saved = load_scene(folder.file("jelly.json"));
  EXPECT_EQ(saved.look.camera_position, opened.look.camera_position);
  testing::expect_same_scene(opened, saved);
}

TEST(SaveCurrentScene, IntoAMissingFolderFailsNamingThePathAndLeavesNothing) {
  TemporaryFolder folder;
  const Scene opened = load_scene("cloth");
  Simulation simulation(opened.network, opened.pins, opened.params, opened.initial_velocity);
  const std::string path = folder.file("no-such-folder/saved.json");
  try {
    save_current_scene(path, opened, simulation, std::nullopt);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
  }
  EXPECT_TRUE(folder.entries().empty());
}

}  // namespace
}  // namespace wobble

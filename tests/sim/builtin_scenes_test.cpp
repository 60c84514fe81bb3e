#include "sim/shapes/builtin_scenes.h"

#include <gtest/gtest.h>

#include "sim/input_error.h"
#include "sim/simulation.h"

namespace {

TEST(BuiltinScenes, ClothHangsFromItsTwoTopCorners) {
  const wobble::Scene scene = wobble::make_builtin_scene("cloth");
  EXPECT_EQ(scene.network.V.rows(), 40 * 40);
  ASSERT_EQ(scene.pins.size(), 2u);
  const Eigen::RowVector3d a = scene.network.V.row(scene.pins[0]);
  const Eigen::RowVector3d b = scene.network.V.row(scene.pins[1]);
  // Both on the top edge (smallest z), at opposite ends, at the highest point.
  EXPECT_EQ(a.z(), scene.network.V.col(2).minCoeff());
  EXPECT_EQ(b.z(), scene.network.V.col(2).minCoeff());
  EXPECT_NEAR(std::abs(a.x() - b.x()), 1.0, 1e-12);
  EXPECT_EQ(a.y(), scene.network.V.col(1).maxCoeff());
  EXPECT_NEAR(scene.network.m.sum(), 0.25, 1e-12);  // 1 m² at 0.25 kg/m²
  EXPECT_EQ(scene.params.gravity, Eigen::Vector3d(0, -9.81, 0));
  EXPECT_EQ(scene.params.gravity_model, wobble::GravityModel::acceleration);
}

TEST(BuiltinScenes, JellyIsPinnedExactlyAtItsBase) {
  const wobble::Scene scene = wobble::make_builtin_scene("jelly");
  EXPECT_EQ(scene.network.V.rows(), 9 * 9 * 9);
  EXPECT_EQ(scene.pins.size(), 81u);
  for (int pin : scene.pins)
    EXPECT_EQ(scene.network.V(pin, 1), 0.0);
  EXPECT_NEAR(scene.network.m.sum(), 200.0 * 0.125, 1e-9);  // 0.5 m cube at 200 kg/m³
  ASSERT_EQ(scene.initial_velocity.rows(), scene.network.V.rows());
  for (int pin : scene.pins)
    EXPECT_EQ(scene.initial_velocity.row(pin).norm(), 0.0);
}

TEST(BuiltinScenes, EveryListedSceneBuildsAndSimulates) {
  for (const std::string& name : wobble::builtin_scene_names()) {
    SCOPED_TRACE(name);
    const wobble::Scene scene = wobble::make_builtin_scene(name);
    EXPECT_EQ(scene.name, name);
    wobble::Simulation simulation(scene.network, scene.pins, scene.params, scene.initial_velocity);
    simulation.apply(wobble::with_setting(simulation.params(), "iterations", 10.0));
    for (int step = 0; step < 5; ++step)
      simulation.step();
    EXPECT_TRUE(simulation.positions().allFinite());
    EXPECT_GT((simulation.positions() - scene.network.V).cwiseAbs().maxCoeff(), 1e-3);
  }
}

TEST(BuiltinScenes, UnknownNameIsRefusedListingTheKnownOnes) {
  try {
    wobble::make_builtin_scene("curtain");
    FAIL() << "accepted an unknown scene";
  } catch (const wobble::InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("'curtain'"), std::string::npos) << message;
    EXPECT_NE(message.find("cloth, jelly"), std::string::npos) << message;
  }
}

}  // namespace

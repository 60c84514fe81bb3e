#include "app/interaction/environment_controls.h"

#include <gtest/gtest.h>

#include "sim/settings/setting_registry.h"
#include "sim/settings/simulation_params.h"

namespace {

using wobble::WindModel;
using wobble::WindParams;

// The wind's switch as the W key and the panel's checkbox turn it (sim/settings: toggle).
wobble::SimulationParams toggled(wobble::SimulationParams params) {
  wobble::toggle(*wobble::find_setting("wind"), params);
  return params;
}

TEST(EnvironmentControls, TurningOnAStillAerodynamicWindGivesTheBreeze) {
  const wobble::SimulationParams still;  // off, aerodynamic, zero velocity
  const wobble::SimulationParams on = toggled(still);
  EXPECT_TRUE(on.wind.on);
  EXPECT_TRUE(on.wind.velocity.isApprox(WindParams::default_breeze().velocity));
  EXPECT_FALSE(toggled(on).wind.on);
  // Off again keeps the breeze's velocity, so the next W brings the same wind back.
  EXPECT_TRUE(toggled(on).wind.velocity.isApprox(on.wind.velocity));
}

TEST(EnvironmentControls, ASceneWindAndTheCourseWindOnlyFlip) {
  wobble::SimulationParams scene;
  scene.wind.velocity = Eigen::Vector3d(0, 0, -2);
  scene.wind.drag = 0.7;
  const wobble::SimulationParams on = toggled(scene);
  EXPECT_TRUE(on.wind.on);
  EXPECT_EQ(on.wind.velocity, scene.wind.velocity);
  EXPECT_EQ(on.wind.drag, 0.7);

  wobble::SimulationParams course;
  course.wind.model = WindModel::course;
  const wobble::SimulationParams course_on = toggled(course);
  EXPECT_TRUE(course_on.wind.on);
  EXPECT_EQ(course_on.wind.model, WindModel::course);
  EXPECT_TRUE(course_on.wind.velocity.isZero());
}

TEST(EnvironmentControls, SpeedAndHeadingRoundTripAndKeepElevation) {
  const Eigen::Vector3d rising(0.0, 1.0, 1.0);  // towards +z, rising at 45°
  EXPECT_NEAR(wobble::heading_degrees(rising), 90.0, 1e-12);
  const Eigen::Vector3d turned = wobble::with_speed_and_heading(rising, 4.0, 180.0);  // towards −x
  EXPECT_NEAR(turned.x(), -4.0 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(turned.y(), 4.0 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(turned.z(), 0.0, 1e-12);
  EXPECT_NEAR(wobble::heading_degrees(Eigen::Vector3d(1.0, 0.0, -1.0)), 315.0, 1e-12);
  EXPECT_TRUE(wobble::with_speed_and_heading(Eigen::Vector3d::Zero(), 2.0, 0.0)
                  .isApprox(Eigen::Vector3d(2.0, 0.0, 0.0)));
}

}  // namespace

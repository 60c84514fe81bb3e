#include "app/interaction/environment_controls.h"

#include <gtest/gtest.h>

namespace {

using wobble::WindModel;
using wobble::WindParams;

TEST(EnvironmentControls, TurningOnAStillAerodynamicWindGivesTheBreeze) {
  const WindParams still;  // off, aerodynamic, zero velocity
  const WindParams on = wobble::toggled_wind(still);
  EXPECT_TRUE(on.on);
  EXPECT_TRUE(on.velocity.isApprox(WindParams::default_breeze().velocity));
  EXPECT_FALSE(wobble::toggled_wind(on).on);
  // Off again keeps the breeze's velocity, so the next W brings the same wind back.
  EXPECT_TRUE(wobble::toggled_wind(on).velocity.isApprox(on.velocity));
}

TEST(EnvironmentControls, ASceneWindAndTheCourseWindOnlyFlip) {
  WindParams scene;
  scene.velocity = Eigen::Vector3d(0, 0, -2);
  scene.drag = 0.7;
  const WindParams on = wobble::toggled_wind(scene);
  EXPECT_TRUE(on.on);
  EXPECT_EQ(on.velocity, scene.velocity);
  EXPECT_EQ(on.drag, 0.7);

  WindParams course;
  course.model = WindModel::course;
  const WindParams course_on = wobble::toggled_wind(course);
  EXPECT_TRUE(course_on.on);
  EXPECT_EQ(course_on.model, WindModel::course);
  EXPECT_TRUE(course_on.velocity.isZero());
}

TEST(EnvironmentControls, SpeedAndHeadingRoundTripAndKeepElevation) {
  WindParams wind;
  wind.velocity = Eigen::Vector3d(0.0, 1.0, 1.0);  // towards +z, rising at 45°
  EXPECT_NEAR(wobble::wind_heading_degrees(wind), 90.0, 1e-12);
  EXPECT_NEAR(wobble::wind_speed(wind), std::sqrt(2.0), 1e-12);
  const WindParams turned = wobble::wind_with_speed_and_heading(wind, 4.0, 180.0);  // towards −x
  EXPECT_NEAR(turned.velocity.x(), -4.0 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(turned.velocity.y(), 4.0 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(turned.velocity.z(), 0.0, 1e-12);
  wind.velocity = Eigen::Vector3d(1.0, 0.0, -1.0);
  EXPECT_NEAR(wobble::wind_heading_degrees(wind), 315.0, 1e-12);
  const WindParams from_still = wobble::wind_with_speed_and_heading(WindParams(), 2.0, 0.0);
  EXPECT_TRUE(from_still.velocity.isApprox(Eigen::Vector3d(2.0, 0.0, 0.0)));
}

TEST(EnvironmentControls, GravityKeepsTheScenesDirection) {
  const Eigen::Vector3d sideways(3.0, -4.0, 0.0);  // |g| = 5
  EXPECT_TRUE(wobble::gravity_with_magnitude(sideways, 10.0).isApprox(Eigen::Vector3d(6, -8, 0)));
  EXPECT_TRUE(wobble::gravity_with_magnitude(sideways, 5.0).isApprox(sideways));
  EXPECT_TRUE(wobble::gravity_with_magnitude(Eigen::Vector3d::Zero(), 2.0)
                  .isApprox(Eigen::Vector3d(0, -2, 0)));
}

}  // namespace

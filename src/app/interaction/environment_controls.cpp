#include "app/interaction/environment_controls.h"

#include <cmath>

namespace wobble {

namespace {

constexpr double pi = 3.14159265358979323846;

}  // namespace

WindParams toggled_wind(const WindParams& wind) {
  if (!wind.on && wind.model == WindModel::aerodynamic && wind.velocity.isZero(0.0)) {
    return WindParams::default_breeze();
  }
  WindParams toggled = wind;
  toggled.on = !wind.on;
  return toggled;
}

double wind_speed(const WindParams& wind) {
  return wind.velocity.norm();
}

double wind_heading_degrees(const WindParams& wind) {
  const double x = wind.velocity.x(), z = wind.velocity.z();
  if (x == 0.0 && z == 0.0) return 0.0;
  double degrees = std::atan2(z, x) * 180.0 / pi;
  if (degrees < 0.0) degrees += 360.0;
  return degrees >= 360.0 ? 0.0 : degrees;
}

WindParams wind_with_speed_and_heading(const WindParams& wind, double speed,
                                       double heading_degrees) {
  const Eigen::Vector3d& v = wind.velocity;
  const double elevation = v.isZero(0.0) ? 0.0 : std::atan2(v.y(), std::hypot(v.x(), v.z()));
  const double heading = heading_degrees * pi / 180.0;
  WindParams changed = wind;
  changed.velocity =
      speed * Eigen::Vector3d(std::cos(elevation) * std::cos(heading), std::sin(elevation),
                              std::cos(elevation) * std::sin(heading));
  return changed;
}

Eigen::Vector3d gravity_with_magnitude(const Eigen::Vector3d& scene_gravity, double magnitude) {
  const double norm = scene_gravity.norm();
  const Eigen::Vector3d direction =
      norm > 0.0 ? Eigen::Vector3d(scene_gravity / norm) : Eigen::Vector3d(0.0, -1.0, 0.0);
  return magnitude * direction;
}

}  // namespace wobble

#include "app/interaction/environment_controls.h"

#include <cmath>

namespace wobble {

namespace {

constexpr double pi = 3.14159265358979323846;

}  // namespace

double heading_degrees(const Eigen::Vector3d& v) {
  const double x = v.x(), z = v.z();
  if (x == 0.0 && z == 0.0) return 0.0;
  double degrees = std::atan2(z, x) * 180.0 / pi;
  if (degrees < 0.0) degrees += 360.0;
  return degrees >= 360.0 ? 0.0 : degrees;
}

Eigen::Vector3d with_speed_and_heading(const Eigen::Vector3d& v, double speed,
                                       double heading_degrees) {
  const double elevation = v.isZero(0.0) ? 0.0 : std::atan2(v.y(), std::hypot(v.x(), v.z()));
  const double heading = heading_degrees * pi / 180.0;
  return speed * Eigen::Vector3d(std::cos(elevation) * std::cos(heading), std::sin(elevation),
                                 std::cos(elevation) * std::sin(heading));
}

}  // namespace wobble

#include "sim/forces/wind.h"

#include <Eigen/Geometry>

#include <cmath>
#include <string>

#include "sim/input_error.h"
#include "sim/value_limits.h"

namespace wobble {

namespace {

constexpr double two_pi = 6.283185307179586;

void check_number(double value, const ValueRange& range, const std::string& what) {
  if (!range.contains(value)) {
    throw InputError(what + ": expected " + expected_in(range) + ", got " + limit_text(value));
  }
}

// A gust profile in [−1, 1]: three sines of unrelated periods (3.1 s, 1.3 s, 0.7 s), so the wind
// never repeats visibly within a demo.
double gust_profile(double s) {
  return (std::sin(two_pi * s / 3.1) + 0.6 * std::sin(two_pi * s / 1.3 + 1.1) +
          0.4 * std::sin(two_pi * s / 0.7 + 2.3)) /
         2.0;
}

}  // namespace

WindParams WindParams::default_breeze() {
  WindParams breeze;
  breeze.on = true;
  breeze.velocity = Eigen::Vector3d(4.0, 0.0, 1.5);
  breeze.gusts = 0.3;
  return breeze;
}

void validate_wind(const WindParams& wind) {
  const std::string velocity =
      outside_limits(wind.velocity.array(), limits::speed, "wind velocity");
  if (!velocity.empty()) throw InputError(velocity);
  check_number(wind.drag, limits::aerodynamic_coefficient, "wind drag");
  check_number(wind.lift, limits::aerodynamic_coefficient, "wind lift");
  check_number(wind.gusts, limits::gust_strength, "wind gusts");
  check_number(wind.air_density, limits::air_density, "wind air_density");
}

Eigen::Vector3d wind_velocity_at(const WindParams& wind, const Eigen::Vector3d& point,
                                 double time) {
  if (wind.gusts == 0.0) return wind.velocity;
  const double speed = wind.velocity.norm();
  if (speed == 0.0) return wind.velocity;
  const double s = time - point.dot(wind.velocity) / (speed * speed);
  return wind.velocity * (1.0 + wind.gusts * gust_profile(s));
}

void AerodynamicWind::add_forces(const StepContext& step, Eigen::MatrixXd& fext) {
  const Eigen::MatrixXi& F = step.rest.F;
  const Eigen::MatrixXd& p = step.current;
  const double inverse_dt = 1.0 / step.dt;
  const double half_rho = 0.5 * wind_.air_density;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const int a = F(f, 0), b = F(f, 1), c = F(f, 2);
    const Eigen::Vector3d pa = p.row(a), pb = p.row(b), pc = p.row(c);
    const Eigen::Vector3d cross = (pb - pa).cross(pc - pa);
    const double twice_area = cross.norm();
    if (!(twice_area > 0.0)) continue;
    const Eigen::Vector3d n = cross / twice_area;
    const double area = 0.5 * twice_area;
    const Eigen::Vector3d moved = (p.row(a) + p.row(b) + p.row(c) - step.previous.row(a) -
                                   step.previous.row(b) - step.previous.row(c))
                                      .transpose();
    const Eigen::Vector3d velocity = moved * (inverse_dt / 3.0);
    const Eigen::Vector3d centroid = (pa + pb + pc) / 3.0;
    const Eigen::Vector3d u = wind_velocity_at(wind_, centroid, step.time) - velocity;
    const double un = u.dot(n);
    Eigen::Vector3d force = half_rho * wind_.drag * area * std::abs(un) * un * n;
    const double speed = u.norm();
    if (wind_.lift != 0.0 && speed > 0.0) {
      const Eigen::Vector3d along = u / speed;
      force += half_rho * wind_.lift * area * un * speed * (n - n.dot(along) * along);
    }
    const Eigen::RowVector3d share = force.transpose() / 3.0;
    fext.row(a) += share;
    fext.row(b) += share;
    fext.row(c) += share;
  }
}

void CourseWind::add_forces(const StepContext& step, Eigen::MatrixXd& fext) {
  for (Eigen::Index i = 0; i < fext.rows(); ++i) {
    const double phi = step.current(i, 0) / rest_diagonal_ + step.time;
    fext(i, 0) = 3.0 + 1.5 * (1.0 + std::cos(5.0 * phi));
    fext(i, 2) = std::sin(phi);
    fext(i, 1) += 1.0 + std::cos(0.3 + phi);
  }
}

std::unique_ptr<StepTerm> make_wind_force(const WindParams& wind, double rest_diagonal) {
  if (!wind.on) return nullptr;
  if (wind.model == WindModel::course) return std::make_unique<CourseWind>(rest_diagonal);
  return std::make_unique<AerodynamicWind>(wind);
}

}  // namespace wobble

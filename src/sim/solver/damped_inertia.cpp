#include "damped_inertia.h"

namespace wobble {

double inertia_scale(double dt, double damping) {
  return (1.0 + damping * dt) / (dt * dt);
}

void inertial_right_hand_side(const Eigen::VectorXd& m, const Eigen::MatrixXd& current,
                              const Eigen::MatrixXd& previous, double dt, double damping,
                              Eigen::MatrixXd& y) {
  const double inverse_dt2 = 1.0 / (dt * dt);
  const double damped = 2.0 + damping * dt;
  y.noalias() = m.asDiagonal() * (damped * current - previous);
  y *= inverse_dt2;
}

void inertial_prediction(const Eigen::MatrixXd& current, const Eigen::MatrixXd& previous, double dt,
                         double damping, Eigen::MatrixXd& p) {
  if (damping == 0.0) {
    p = 2.0 * current - previous;
  } else {
    const double cdt = damping * dt;
    p = ((2.0 + cdt) * current - previous) / (1.0 + cdt);
  }
}

}  // namespace wobble

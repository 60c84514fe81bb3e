#include "pin_weight.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace {

template <typename Factor, typename Matrix>
FactoredPinWeight fit_pin_weight(const Factor& factor, const Matrix& Q0, const Matrix& C) {
  // x with a different value at every vertex, so no pin can hide behind a zero.
  const Eigen::Index n = Q0.rows();
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  const Eigen::VectorXd freed = x - factor.solve(Eigen::VectorXd(Q0 * x));
  const Eigen::VectorXd held = factor.solve(Eigen::VectorXd(C.transpose() * (C * x)));
  FactoredPinWeight found;
  const double held_squared = held.squaredNorm();
  if (!(held_squared > 0) || !std::isfinite(held_squared) || !freed.allFinite()) return found;
  found.w = freed.dot(held) / held_squared;
  const double residual = (freed - found.w * held).norm();
  found.fits = std::isfinite(found.w) && residual <= 1e-6 * freed.norm() + 1e-300;
  // A Q with no pin term leaves nothing to fit: x − Q⁻¹Q0 x is zero.
  if (freed.norm() <= 1e-12 * x.norm()) found.w = 0, found.fits = true;
  return found;
}

}  // namespace

bool acceptable_pin_weight(double w) {
  // Inclusive, to the rounding of a weight found from solves: 1e12 is found as 1e12 (1 ± 1e-12).
  return w >= kLightestPinWeight * (1 - 1e-9) && w <= kHeaviestPinWeight * (1 + 1e-9);
}

std::string pin_weight_text(double w) {
  if (!std::isfinite(w)) return "undetermined";
  if (w == 0) return "0";
  char text[40];
  std::snprintf(text, sizeof text, "%.4g", w);
  std::string written = text;
  // 1e+10 → 1e10, 2.5e+07 → 2.5e7
  const size_t e = written.find('e');
  if (e != std::string::npos) {
    std::string exponent = written.substr(e + 1);
    const bool negative = exponent[0] == '-';
    exponent.erase(0, 1);
    while (exponent.size() > 1 && exponent[0] == '0')
      exponent.erase(0, 1);
    written = written.substr(0, e + 1) + (negative ? "-" : "") + exponent;
  }
  return written;
}

FactoredPinWeight factored_pin_weight(const Eigen::LLT<Eigen::MatrixXd>& factor,
                                      const Eigen::MatrixXd& Q0, const Eigen::MatrixXd& C) {
  return fit_pin_weight(factor, Q0, C);
}

FactoredPinWeight factored_pin_weight(
    const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>& factor,
    const Eigen::SparseMatrix<double>& Q0, const Eigen::SparseMatrix<double>& C) {
  return fit_pin_weight(factor, Q0, C);
}

Eigen::MatrixXd quadratic_without_pins(double k, double delta_t, const Eigen::MatrixXd& M,
                                       const Eigen::MatrixXd& A) {
  return k * A.transpose() * A + M / (delta_t * delta_t);
}

Eigen::SparseMatrix<double> quadratic_without_pins(double k, double delta_t,
                                                   const Eigen::SparseMatrix<double>& M,
                                                   const Eigen::SparseMatrix<double>& A) {
  const Eigen::SparseMatrix<double> AtA = A.transpose() * A;
  return k * AtA + M / (delta_t * delta_t);
}

double step_pin_weight(const Eigen::RowVector3d& rest, const Eigen::RowVector3d& stepped,
                       double mass, double delta_t, double factored_weight) {
  const double ratio = stepped.dot(rest) / rest.squaredNorm();
  // Off the line through p₀ by more than rounding: not a weighted pull towards p₀.
  if (!std::isfinite(ratio) || (stepped - ratio * rest).norm() > 1e-6 * rest.norm())
    return std::numeric_limits<double>::quiet_NaN();
  const double inertia = mass / (delta_t * delta_t);
  return ratio * (inertia + factored_weight) - inertia;
}

#include "chebyshev.h"

#include <algorithm>
#include <cmath>

namespace wobble {

ChebyshevAcceleration::ChebyshevAcceleration(Eigen::Index vertices)
    : older_(vertices, 3), scratch_(vertices, 3) {}

double ChebyshevAcceleration::estimate_spectral_radius(const std::vector<double>& update_norms) {
  const std::size_t half = update_norms.size() / 2;
  double log_ratio = 0.0;
  int count = 0;
  for (std::size_t k = std::max<std::size_t>(half, 1); k < update_norms.size(); ++k) {
    if (update_norms[k - 1] > 0.0 && update_norms[k] > 0.0) {
      log_ratio += std::log(update_norms[k] / update_norms[k - 1]);
      ++count;
    }
  }
  if (count == 0) return 0.0;
  return std::clamp(std::exp(log_ratio / count), 0.0, 0.999);
}

void ChebyshevAcceleration::start(const Eigen::MatrixXd& q0) {
  older_ = q0;
  omega_ = 1.0;
}

void ChebyshevAcceleration::accelerate(int iteration, const Eigen::MatrixXd& solved,
                                       Eigen::MatrixXd& q) {
  // Chebyshev polynomials on [0, ρ]: the paper's recurrence with σ = ρ/(2 − ρ) in place of ρ,
  // and every step stretched by 2/(2 − ρ) (see the class comment).
  const double sigma = rho_ / (2.0 - rho_), stretch = 2.0 / (2.0 - rho_);
  const double sigma2 = sigma * sigma;
  if (iteration < delay_) {
    omega_ = 1.0;
  } else if (iteration == delay_) {
    omega_ = 2.0 / (2.0 - sigma2);
  } else {
    omega_ = 4.0 / (4.0 - sigma2 * omega_);
  }
  scratch_ = omega_ * (gamma_ * stretch * (solved - q) + q - older_) + older_;
  older_.swap(q);
  q.swap(scratch_);
}

}  // namespace wobble

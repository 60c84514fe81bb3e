#ifndef WOBBLE_SIM_CHEBYSHEV_H
#define WOBBLE_SIM_CHEBYSHEV_H

#include <Eigen/Core>
#include <vector>

namespace wobble {

// Chebyshev semi-iterative acceleration of the local-global iterations (Wang 2015, "A Chebyshev
// Semi-Iterative Approach for Accelerating Projective and Position-based Dynamics"). After each
// plain iteration gives q̂, the iterate becomes
//   q⁽ᵏ⁺¹⁾ = ω_{k+1} (γ s (q̂ − q⁽ᵏ⁾) + q⁽ᵏ⁾ − q⁽ᵏ⁻¹⁾) + q⁽ᵏ⁻¹⁾,
//   ω = 1 before iteration S, ω_S = 2/(2 − σ²), then ω_{k+1} = 4/(4 − σ² ω_k),
// with ρ the spectral radius of the plain iteration, γ an under-relaxation and S a delayed start
// (iterations left unaccelerated while the nonlinear iteration settles).
//
// The paper takes σ = ρ and s = 1: Chebyshev polynomials on [−ρ, ρ], for an iteration whose
// error may flip sign. This one's does not: its updates shrink steadily, their ratio settling at
// ρ, so its spectrum lies in [0, ρ]. The polynomials on [0, ρ] give σ = ρ/(2 − ρ) and a stretch
// s = 2/(2 − ρ) of every step, and shrink the error faster.
//
// Those polynomials do little at the ends of [0, ρ] for few iterations: one accelerated
// iteration flips the sign of the error's fast components (λ near 0) and keeps most of them, and
// a drag with 1 to 3 iterations threw the cloth away. So the local-global solver
// (local_global_solver.cpp) makes the last iteration of every step a plain one, which multiplies
// each fast component by its λ. The defaults are S = 0 (the recurrence from the first
// iteration) and γ = 1; docs/performance.md ("Chebyshev against plain iterations") gives the
// measurements behind [0, ρ], the last plain iteration, S and γ.
class ChebyshevAcceleration {
 public:
  static constexpr double default_under_relaxation = 1.0;
  static constexpr int default_delay = 0;

  explicit ChebyshevAcceleration(Eigen::Index vertices);

  // ρ from the norms of successive updates ‖q⁽ᵏ⁺¹⁾ − q⁽ᵏ⁾‖ of a plain run: their ratio settles at
  // the spectral radius. Uses the second half of the run, where it has settled; clamped to
  // [0, 0.999] so ω stays finite.
  static double estimate_spectral_radius(const std::vector<double>& update_norms);

  void set_spectral_radius(double rho) { rho_ = rho; }
  double spectral_radius() const { return rho_; }
  void set_under_relaxation(double gamma) { gamma_ = gamma; }
  double under_relaxation() const { return gamma_; }
  void set_delay(int delay) { delay_ = delay; }
  int delay() const { return delay_; }

  // At the start of a step, from the initial iterate q⁽⁰⁾.
  void start(const Eigen::MatrixXd& q0);
  // After iteration `iteration` (from 0): `solved` is q̂, `q` holds q⁽ᵏ⁾ and receives q⁽ᵏ⁺¹⁾.
  void accelerate(int iteration, const Eigen::MatrixXd& solved, Eigen::MatrixXd& q);

 private:
  double rho_ = 0.0;
  double omega_ = 1.0;
  double gamma_ = default_under_relaxation;
  int delay_ = default_delay;
  Eigen::MatrixXd older_, scratch_;  // q⁽ᵏ⁻¹⁾, and room for q⁽ᵏ⁺¹⁾
};

}  // namespace wobble

#endif

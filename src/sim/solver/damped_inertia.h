#ifndef WOBBLE_SIM_SOLVER_DAMPED_INERTIA_H
#define WOBBLE_SIM_SOLVER_DAMPED_INERTIA_H

#include <Eigen/Core>

namespace wobble {

// The inertia term of a step with mass-proportional damping c (1/s):
//   (1 + cΔt)/(2Δt²) ‖p − p̂‖²_M,  p̂ = ((2 + cΔt)pᵗ − pᵗ⁻ᐞᵗ)/(1 + cΔt)
// It puts (1 + cΔt)M/Δt² on Q's diagonal and M((2 + cΔt)pᵗ − pᵗ⁻ᐞᵗ)/Δt² into y. Damping lives
// here, not as a force: folded into Q it damps every step implicitly (c = 0: none, and exactly
// the seed's inertia).

// (1 + cΔt)/Δt² (1/s²): what each mass is multiplied by on Q's diagonal.
double inertia_scale(double dt, double damping);

// y = M((2 + cΔt)pᵗ − pᵗ⁻ᐞᵗ)/Δt², the inertia's part of the step's fixed right-hand side.
//   m  #V masses (kg);  current, previous  #V by 3 pᵗ, pᵗ⁻ᐞᵗ (m);  y  #V by 3 (N), its size kept
void inertial_right_hand_side(const Eigen::VectorXd& m, const Eigen::MatrixXd& current,
                              const Eigen::MatrixXd& previous, double dt, double damping,
                              Eigen::MatrixXd& y);

// p = p̂, where inertia and damping alone carry each vertex (#V by 3, m).
void inertial_prediction(const Eigen::MatrixXd& current, const Eigen::MatrixXd& previous, double dt,
                         double damping, Eigen::MatrixXd& p);

}  // namespace wobble

#endif

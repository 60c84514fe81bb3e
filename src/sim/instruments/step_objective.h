#ifndef WOBBLE_SIM_INSTRUMENTS_STEP_OBJECTIVE_H
#define WOBBLE_SIM_INSTRUMENTS_STEP_OBJECTIVE_H

#include <Eigen/Core>

namespace wobble {

// Everything the objective of one time step depends on besides the iterate.
struct StepObjectiveTerms {
  const Eigen::MatrixXi& E;         // #E by 2 springs
  const Eigen::VectorXd& r;         // #E rest lengths (m)
  const Eigen::VectorXd& m;         // #V masses (kg)
  double k = 0.0;                   // N/m
  double dt = 0.0;                  // s
  double damping = 0.0;             // c (1/s)
  const Eigen::MatrixXd& current;   // #V by 3 pᵗ (m)
  const Eigen::MatrixXd& previous;  // #V by 3 pᵗ⁻ᐞᵗ (m)
  const Eigen::MatrixXd& fext;      // #V by 3 external forces (N)
};

// The springs' and the inertia's part of the energy one step minimizes, at the iterate p (#V by 3,
// m), in J:
//   ½k Σ(‖pᵢ−pⱼ‖−rᵢⱼ)² + (1 + cΔt)/(2Δt²)‖p − p̂‖²_M − pᵀf_ext
// with p̂ = ((2 + cΔt)pᵗ − pᵗ⁻ᐞᵗ)/(1 + cΔt), the inertial prediction (c = 0: 2pᵗ − pᵗ⁻ᐞᵗ).
// The step's terms (the pins' (w/2)‖Cp − C p_target‖², contact) add theirs (terms/step_term.h);
// with them, up to a constant, this is the objective Q and y encode, so the local-global
// iteration never raises it. If `gradient` is given (resized to #V by 3 if needed), it receives the
// objective's gradient in N; a global solve leaves it equal to k Aᵀ(d(p_before) − d(p)), which is
// zero only at a minimum. One pass over the springs and one over the vertices; allocates nothing
// when `gradient` already has its size.
double step_objective(const StepObjectiveTerms& terms, const Eigen::MatrixXd& p,
                      Eigen::MatrixXd* gradient = nullptr);

// The terms of step_objective that live on the vertices (inertia and −pᵀf_ext), in J:
// step_objective(terms, p) = ½k Σ(‖pᵢ−pⱼ‖−rᵢⱼ)² + step_objective_vertex_terms(terms, p).
double step_objective_vertex_terms(const StepObjectiveTerms& terms, const Eigen::MatrixXd& p);

}  // namespace wobble

#endif

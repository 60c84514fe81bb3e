#ifndef WOBBLE_SIM_INSTRUMENTS_ITERATE_MEASURE_H
#define WOBBLE_SIM_INSTRUMENTS_ITERATE_MEASURE_H

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "step_objective.h"

namespace wobble {

// The step energy E(p) (J) and ‖∇E(p)‖ (N) at a local-global iterate p, cheaply: from the
// right-hand side rhs = k Aᵀd(p) + y its local step has just made, ∇E(p) = Q p − rhs (k AᵀA p −
// k Aᵀd(p) is the springs' part, the rest the inertia, f_ext and the pins), and
//   E(p) = ½k Σ(‖pᵢ − pⱼ‖ − rᵢⱼ)² + step_objective_vertex_terms(p).
// When p came straight out of a double-precision solve of Q p = b (b the previous iterate's
// rhs), Q p is b to rounding and the product is skipped: it would cost as much as a local step.
// Allocates nothing once sized.
class IterateMeasure {
 public:
  // Room for #V by 3 (a no-op when already that size).
  void resize(Eigen::Index vertices);

  struct Result {
    double energy = 0.0;         // J
    double gradient_norm = 0.0;  // N
  };
  //   terms  the step's objective;  Q  #V by #V;  p, rhs  #V by 3
  //   springs  Σ(‖pᵢ − pⱼ‖ − rᵢⱼ)² at p (m², from the same local step)
  //   plain_solve  p is Q⁻¹ of the previous call's rhs, solved in double precision
  Result measure(const StepObjectiveTerms& terms, const Eigen::SparseMatrix<double>& Q,
                 const Eigen::MatrixXd& p, const Eigen::MatrixXd& rhs, double springs,
                 bool plain_solve);

 private:
  Eigen::MatrixXd gradient_, previous_rhs_;  // #V by 3
};

}  // namespace wobble

#endif

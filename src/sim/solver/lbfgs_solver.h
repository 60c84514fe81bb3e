#ifndef WOBBLE_SIM_SOLVER_LBFGS_SOLVER_H
#define WOBBLE_SIM_SOLVER_LBFGS_SOLVER_H

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "sim/solver/step_solver.h"

namespace wobble {

// L-BFGS on the step energy, as in Liu, Bouaziz and Kavan 2017, "Quasi-Newton Methods for
// Real-Time Simulation of Hyperelastic Materials" ("lbfgs"). Each iteration, from the iterate p
// (#V by 3) and its gradient g = ∇E(p):
//   direction: d = −H g by the two-loop recursion over the last `history` pairs
//     (sᵢ = pᵢ₊₁ − pᵢ, yᵢ = gᵢ₊₁ − gᵢ), with the local-global matrix Q as the initial Hessian:
//     its inverse applied through the factorization the Simulation already keeps (one solve);
//   line search: p + αd, α = 1, ½, ¼, … until the energy falls by Armijo's rule
//     E(p + αd) ≤ E(p) + 10⁻⁴ α gᵀd; a step that cannot lower it ends the iterations there, so
//     the energy never rises from one iterate to the next.
// E is the whole step energy: springs, inertia with damping, f_ext (gravity, wind) and every term
// of the step's list (the pins, contact with its friction, self-contact: StepProblem::energy); a
// term that bounds the iterate (self-contact) moves an accepted step back within its bounds, and
// the history then starts again. An iteration costs one solve with
// Q, one pass over the springs and vertices for E and ∇E, and 4·history products of #V by 3
// arrays; usually α = 1 is taken and the line search costs nothing more. The same iteration cap
// as local-global (settings.iterations); settings.chebyshev does not apply.
class LbfgsSolver : public StepSolver {
 public:
  // Pairs kept. Liu et al. use 5 to 7 and found more did not pay; 5 costs 20 products of #V by
  // 3 arrays an iteration, a tenth of a 128×128 cloth's solve.
  static constexpr int history = 5;
  // Halvings of α before the line search gives up (the energy is then flat to rounding).
  static constexpr int max_halvings = 12;

  explicit LbfgsSolver(Eigen::Index vertices);

  const char* name() const override { return "lbfgs"; }
  void solve(const StepProblem& problem, StepObservers& observers, Eigen::MatrixXd& p,
             StepTiming& timing) override;

  // Iterations of the last solve that took a step (the rest found no lower energy), and the line
  // search's energy evaluations beyond the first of each iteration.
  int last_iterations() const { return last_iterations_; }
  int last_extra_evaluations() const { return last_extra_evaluations_; }

 private:
  // E(p) and ∇E(p) into `gradient`.
  double evaluate(const StepProblem& problem, const Eigen::MatrixXd& p,
                  Eigen::MatrixXd& gradient) const;
  // direction_ = −H gradient_ (two-loop recursion, Q as the initial Hessian).
  void find_direction(const StepProblem& problem);

  Eigen::MatrixXd gradient_, direction_, trial_, trial_gradient_, work_;  // #V by 3
  std::vector<Eigen::MatrixXd> s_, y_;                                    // history, #V by 3
  std::vector<double> rho_, alpha_;
  int stored_ = 0, newest_ = -1;  // pairs held, and where the newest is
  int last_iterations_ = 0, last_extra_evaluations_ = 0;
};

std::unique_ptr<StepSolver> make_lbfgs_solver(Eigen::Index vertices);

}  // namespace wobble

#endif

#ifndef WOBBLE_SIM_SOLVER_LOCAL_GLOBAL_SOLVER_H
#define WOBBLE_SIM_SOLVER_LOCAL_GLOBAL_SOLVER_H

#include <Eigen/Core>
#include <memory>

#include "sim/instruments/iterate_measure.h"
#include "sim/solver/chebyshev.h"
#include "sim/solver/step_solver.h"

namespace wobble {

// The local-global iteration of Liu et al. 2013 ("local-global"), with optional Chebyshev
// acceleration (Wang 2015, settings.chebyshev). Each iteration, from the iterate p (#V by 3):
//   local:  d_e = r_e (p_i − p_j)/‖p_i − p_j‖ for every spring,
//   global: Q p = k Aᵀd + y, through Q's prefactored Cholesky factor.
// It never raises the step energy. Accelerated, every iteration but the last is extrapolated
// (see chebyshev.h); the last stays plain.
class LocalGlobalSolver : public StepSolver {
 public:
  explicit LocalGlobalSolver(Eigen::Index vertices);

  const char* name() const override { return "local-global"; }
  // Turning Chebyshev on for the first time estimates ρ with chebyshev_calibration_iterations
  // plain iterations from `p`.
  void prepare(const StepProblem& problem, Eigen::MatrixXd& p) override;
  void solve(const StepProblem& problem, StepObservers& observers, Eigen::MatrixXd& p,
             StepTiming& timing) override;
  double spectral_radius() const override { return chebyshev_.spectral_radius(); }
  bool extrapolates() const override { return extrapolates_; }

  // The plain iterations of the calibration; ρ comes from the second half.
  static constexpr int chebyshev_calibration_iterations = 100;

 private:
  // p = the accelerated iterate from p and the plain solve solved_.
  void accelerate(int iteration, bool restart_on_growth, Eigen::MatrixXd& p);
  void calibrate(const StepProblem& problem, Eigen::MatrixXd& p);

  Eigen::MatrixXd rhs_;     // #V by 3: k Aᵀd(p) + y
  Eigen::MatrixXd solved_;  // #V by 3: the plain iterate q̂, when accelerating
  ChebyshevAcceleration chebyshev_;
  bool calibrated_ = false;
  bool extrapolates_ = false;  // settings.chebyshev, as last prepared
  double last_update_ = 0.0;   // ‖q̂ − q‖² of the last accelerated iteration
  int restart_iteration_ = 0;  // where the recurrence last restarted in this step
  IterateMeasure measure_;     // while an observer wants measures
};

std::unique_ptr<StepSolver> make_local_global_solver(Eigen::Index vertices);

}  // namespace wobble

#endif

#ifndef WOBBLE_SIM_SIMULATION_H
#define WOBBLE_SIM_SIMULATION_H

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sim/constraints/pins.h"
#include "sim/instruments/convergence_recorder.h"
#include "sim/instruments/frame_energy.h"
#include "sim/instruments/iteration_callback.h"
#include "sim/instruments/step_objective.h"
#include "sim/instruments/step_observer.h"
#include "sim/settings/setting_registry.h"
#include "sim/settings/simulation_params.h"
#include "sim/solver/local_global_solver.h"
#include "sim/solver/local_step.h"
#include "sim/solver/step_solver.h"
#include "sim/solver/system_matrix.h"
#include "sim/terms/step_term.h"
#include "sim/terms/step_terms.h"
#include "spring_network.h"
#include "value_limits.h"

namespace wobble {

// What became of a step. Anything but `ok` means the step was rolled back: the positions are
// those before it, and it does not count in steps_taken().
enum class StepStatus {
  ok,
  not_finite,  // a position became NaN or infinite
  jumped,      // a vertex moved farther than Simulation::jump_limit() from where inertia and
               // gravity alone would have taken it
};

// A mass-spring network advanced by the fast local-global method of Liu et al. 2013, with pins
// whose targets can move. This is what the viewer and the command line drive, one step() a frame.
//
// Each step minimizes, over p (#V by 3),
//   ½k Σ(‖pᵢ−pⱼ‖−rᵢⱼ)² + (1/2Δt²)‖p − 2pᵗ + pᵗ⁻ᐞᵗ‖²_M − pᵀf_ext + (w/2)‖Cp − C p_target‖²
// with `iterations` local-global iterations starting from pᵗ:
//   local:  d_e = r_e (p_i − p_j)/‖p_i − p_j‖
//   global: Q p = k Aᵀd + y,  Q = k AᵀA + (1 + cΔt)M/Δt² + w CᵀC,
//           y = M((2 + cΔt)pᵗ − pᵗ⁻ᐞᵗ)/Δt² + f_ext + w CᵀC p_target,  w = 1e10,
// c the damping (0 by default). Every term beyond the springs and the inertia is one object in
// one list (terms/step_terms.h, in the order terms/term_registry.h gives): the pins
// (constraints/pins.h: w CᵀC on Q's diagonal, w CᵀC p_target in y), then the terms the
// registered factories make for the settings (sim/registered_terms.cpp: the built-in ones, and
// any term registered from outside). What a term needs of the step (gravity, μ, the solver's
// extrapolation, Q's diagonal) reaches it through the StepContext; its own figures reach
// last_step_timing().figures, and its own accessors term<Term>(). With every pin target at its
// rest position, no damping and no term made this is exactly fast_mass_springs_step_sparse.
//
// Each step calls, in this order:
//   forces      f_ext = gravity (forces/gravity.h) + each term's forces
//   y           the damped inertia (solver/damped_inertia.h), f_ext, the terms' fixed part
//   begin       each term chooses its set from the first iterate; Q refactorized when a term's
//               weights on its diagonal changed
//   solver      the registered StepSolver named by params.solver (solver/step_solver.h;
//               local-global by default, or lbfgs), with Q from solver/system_matrix.h, every
//               term through the StepProblem, reporting to the observers
//               (instruments/step_observer.h: the convergence trace, the callback)
//   project     each term's last guard after the solve, in list order
//   report      each term's figures into last_step_timing().figures
//
// Cost of each change (a setting's is its declaration's, sim/settings/built_in_settings.cpp):
//   set_pin_target           right-hand side only: no factorization
//   k, dt, damping, pin,     numeric re-factorization of Q, reusing the symbolic analysis
//   unpin, reset,              (Q's sparsity pattern never changes: its diagonal is always stored)
//   a step whose term
//   changed its weights
//   iterations, gravity,     nothing precomputed
//   set_state, friction
//   a term's settings        the terms made anew where their entries say the old ones no longer
//                            serve (terms/term_registry.h)
class Simulation {
 public:
  static constexpr double pin_weight = Pins::weight;  // w
  static constexpr int max_iterations = limits::max_iterations;

  // Throws InputError when the network, a pin index or a parameter is invalid.
  //   pins              indices of initially pinned vertices; targets start at rest positions
  //   initial_velocity  #V by 3 (m/s), or empty for rest
  Simulation(SpringNetwork network, const std::vector<int>& pins, const SimulationParams& params,
             Eigen::MatrixXd initial_velocity = Eigen::MatrixXd());

  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // Advance one time step of params().dt seconds. A step that produces a non-finite position,
  // or moves a vertex more than jump_limit() away from its inertial prediction 2pᵗ − pᵗ⁻ᐞᵗ, is
  // rolled back: the state stays what it was, so nothing non-finite ever leaves the simulation.
  // The caller decides what to do next (the viewer pauses; a headless run stops).
  StepStatus step();
  StepStatus last_step_status() const { return last_status_; }
  // The largest move a step may make away from its inertial prediction: 100 times the diagonal
  // of the rest shape's bounding box (m). No real step comes close: a dragged pin moves a few
  // diagonals a frame at most, and free fall follows the prediction exactly.
  double jump_limit() const { return jump_limit_; }
  // One line for a user about a failed step, with what to try.
  static std::string describe(StepStatus status);
  // Back to the initial state: rest positions, initial velocity, initial pins at rest targets,
  // every term as it started (StepTerm::reset), time 0. Parameters (k, dt, iterations, gravity,
  // damping, wind, friction) keep their current values.
  void reset();
  // Replace the state: positions at the current and previous time steps, each #V by 3 (m).
  // Pins, targets and parameters are unchanged. Throws InputError for a wrong shape or a
  // non-finite value, leaving the state as it was.
  void set_state(const Eigen::MatrixXd& current, const Eigen::MatrixXd& previous);

  // The one way to change settings: takes a whole settings value and does only the work the
  // difference from the settings in force needs, the costs of the settings that changed (their
  // declarations, sim/settings/setting_registry.h): k, dt, damping (and an added setting whose
  // cost is refactorize) a numeric re-factorization; the solver or Chebyshev the solver's
  // preparation; the wind, self-collision and added settings the terms anew (those whose
  // entries say the old ones no longer serve); gravity, friction, iterations a value. A new dt
  // keeps every vertex's velocity (pᵗ − pᵗ⁻ᐞᵗ)/Δt by rescaling the previous positions.
  // Chebyshev turned on for the first time estimates ρ with a short run of plain iterations from
  // the current state (which it leaves unchanged). What the terms were made with as the
  // simulation started, and single_precision_solve_above, stay so (kept_while_running,
  // settings/simulation_params.h). Throws InputError, changing nothing, for a
  // value out of its limits, an unknown solver or too many iterations for the mesh.
  //   simulation.apply(with_setting(simulation.params(), "k", 2000.0));
  void apply(const SimulationParams& params);
  // The plain iterations of the run that estimates Chebyshev's ρ; ρ comes from the second half.
  static constexpr int chebyshev_calibration_iterations =
      LocalGlobalSolver::chebyshev_calibration_iterations;
  // The spectral radius the acceleration uses; 0 until estimated.
  double chebyshev_spectral_radius() const { return solver_->spectral_radius(); }

  // Simulated time (s): the sum of the accepted steps' Δt since the start or the last reset.
  double time() const { return time_; }

  // Pin vertex i where it is now (target = current position). No-op if already pinned.
  void pin(int i);
  // Release vertex i. No-op if it is not pinned.
  void unpin(int i);
  // Move the target of pinned vertex i (m). Throws std::invalid_argument if i is not pinned.
  void set_pin_target(int i, const Eigen::Vector3d& target);

  bool is_pinned(int i) const;
  // Pinned vertex indices in increasing order.
  std::vector<int> pinned_vertices() const;
  int pin_count() const { return pins_.count(); }
  Eigen::Vector3d pin_target(int i) const;

  // Called after every global solve of every step with the iteration number (0-based) and the
  // current iterate p (#V by 3). Meant for teaching and tests: it slows stepping down.
  void set_iteration_observer(std::function<void(int, const Eigen::MatrixXd&)> observer);
  // The energy that the step now about to be taken minimizes, evaluated at p (#V by 3), in J
  // (see step_objective.h); `gradient`, if given, receives its gradient (#V by 3, N).
  double step_energy(const Eigen::MatrixXd& p, Eigen::MatrixXd* gradient = nullptr) const;
  // While on, every step records its objective and gradient norm at each iterate in
  // last_convergence(): one extra pass over the springs per iteration (the cost shows in
  // last_step_timing().instruments_ms). Off by default; off costs nothing.
  void set_convergence_recording(bool on);
  bool records_convergence() const { return record_convergence_; }
  // The trace of the last step taken while recording (empty before one).
  const ConvergenceTrace& last_convergence() const { return recorder_.trace(); }

  const SpringNetwork& rest() const { return network_; }
  const Eigen::VectorXd& rest_lengths() const { return r_; }
  const SimulationParams& params() const { return params_; }
  // #V by 3 positions at the current and at the previous time step (m).
  const Eigen::MatrixXd& positions() const { return current_; }
  const Eigen::MatrixXd& previous_positions() const { return previous_; }
  // #V by 3 velocities (current − previous)/Δt (m/s).
  Eigen::MatrixXd velocities() const;
  // #V by 3 external forces f_ext (N).
  const Eigen::MatrixXd& external_forces() const { return fext_; }
  // #V by 3 gravity's share of f_ext (N).
  const Eigen::MatrixXd& gravity_forces() const { return gravity_fext_; }
  long steps_taken() const { return steps_taken_; }

  // The last step's timing, with every term's figures by name.
  const StepTiming& last_step_timing() const { return timing_; }
  // The step's terms in step order.
  const StepTerms& terms() const { return terms_; }
  // The step's term of type Term, or nullptr when none is made (its own accessors and edits).
  template <typename Term>
  Term* term() {
    return terms_.find<Term>();
  }
  template <typename Term>
  const Term* term() const {
    return terms_.find<Term>();
  }
  // Time spent in the constructor: rest lengths, Q's pattern, analysis and first factorization.
  double precompute_ms() const { return precompute_ms_; }
  // How often Q was analysed symbolically (once, in the constructor) and factorized numerically.
  int symbolic_analyses() const { return system_.symbolic_analyses(); }
  int numeric_factorizations() const { return system_.numeric_factorizations(); }
  // Nonzeros of the Cholesky factor L of Q, its diagonal included.
  long factor_nonzeros() const { return system_.cholesky().factor_nonzeros(); }
  // The most iterations a step of this mesh may take (limits::max_step_work): its springs and
  // its factor's nonzeros are one iteration's work. At least 1 and at most max_iterations.
  int max_iterations_for_mesh() const;
  double factorization_work() const { return system_.cholesky().factorization_work(); }
  // Whether the solve reads the factor's values rounded to float (a large factor).
  bool solves_in_single_precision() const {
    return system_.cholesky().solves_in_single_precision();
  }

 private:
  // The terms (terms/term_registry.h) for the current params, kept where they still serve those
  // they were made for (`before`; none: all made), and the list again.
  void rebuild_terms(const SimulationParams* before);
  // fext_ = gravity plus this step's forces (wind).
  void apply_forces();
  // y_ = the damped inertia + f_ext + the terms' fixed part (w CᵀC p_target): fixed for the
  // whole step.
  void compute_y();
  // next_ = the first iterate of a step, as params_.first_iterate says.
  void start_iterate();
  // The solver's prepare() on the step about to be taken (see StepSolver::prepare).
  void prepare_solver();
  StepContext step_context() const;
  StepProblem step_problem();
  // Q's values from k, Δt, damping, the masses and every term's diagonal, factorized.
  void refactorize();
  void update_observers();
  // InputError unless `iterations` fit max_iterations_for_mesh; before the analysis
  // (`analyzed` false) the factor is taken as its diagonal alone, a lower bound.
  void check_step_work(int iterations, bool analyzed) const;
  StepStatus check_step() const;

  SpringNetwork network_;
  SimulationParams params_;
  Eigen::MatrixXd initial_velocity_;
  Eigen::VectorXd r_;
  Pins pins_;

  Eigen::MatrixXd previous_, current_, next_;  // pᵗ⁻ᐞᵗ, pᵗ and the iterate, #V by 3
  Eigen::MatrixXd gravity_fext_;               // #V by 3 gravity alone (N)
  Eigen::MatrixXd fext_, y_;                   // #V by 3 buffers kept to avoid allocation
  // The terms after the pins, one slot per entry of terms/term_registry.h (null where off).
  std::vector<std::unique_ptr<StepTerm>> made_terms_;
  bool any_term_made_ = false;  // whether any slot holds a term (else fext_ is gravity alone)
  StepTerms terms_;             // pins_ and made_terms_, in step order
  Eigen::VectorXd base_diagonal_, inertia_;  // #V: Q's diagonal without the terms, its inertia
  double rest_diagonal_ = 0.0;               // of the rest shape's bounding box (m)
  double time_ = 0.0;

  SystemMatrix system_;  // Q and its factorization
  std::unique_ptr<LocalStep> local_step_;
  std::unique_ptr<StepSolver> solver_;

  IterationCallback callback_;
  bool record_convergence_ = false;
  ConvergenceRecorder recorder_;
  StepObservers observers_;
  StepTiming timing_;
  double precompute_ms_ = 0.0;
  long steps_taken_ = 0;
  double jump_limit_ = 0.0;
  StepStatus last_status_ = StepStatus::ok;
};

// The energy of `simulation` now (instruments/frame_energy.h).
FrameEnergy frame_energy(const Simulation& simulation);

}  // namespace wobble

#endif

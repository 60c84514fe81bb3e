#ifndef WOBBLE_SIM_SOLVER_STEP_SOLVER_H
#define WOBBLE_SIM_SOLVER_STEP_SOLVER_H

#include <Eigen/Core>
#include <vector>

#include "sim/instruments/step_objective.h"
#include "sim/instruments/step_observer.h"
#include "sim/solver/local_step.h"
#include "sim/solver/system_matrix.h"
#include "sim/spring_network.h"
#include "sim/terms/step_terms.h"

namespace wobble {

// One time step's minimization problem, as the Simulation hands it to a solver: minimize over
// p (#V by 3, m) the step energy
//   E(p) = ½k Σ(‖pᵢ−pⱼ‖−rᵢⱼ)² + (1 + cΔt)/(2Δt²)‖p − p̂‖²_M − pᵀf_ext + Σ_terms E_term(p)
// (see step_objective.h), the terms those of the step's list (terms/step_terms.h): the pins'
// (w/2)‖Cp − C p_target‖², contact with the colliders, self-contact, ... Its quadratic part is
// ½pᵀQp − pᵀy with
//   Q = k AᵀA + (1 + cΔt)M/Δt² + D  (prefactored; D the terms' diagonal: w CᵀC, contact's κ),
//   y = M((2 + cΔt)pᵗ − pᵗ⁻ᐞᵗ)/Δt² + f_ext + the terms' fixed part (w CᵀC p_target),
// so that ∇E(p) = Q p − rhs(p), rhs(p) = k Aᵀd(p) + y + the terms' targets at p.
//
// The settings a solver reads.
struct SolveSettings {
  double k;        // spring stiffness (N/m)
  double dt;       // Δt (s)
  double damping;  // c (1/s)
  int iterations;  // per step
  bool chebyshev;  // Chebyshev's acceleration (a solver that has one)
};

// A solver sees the terms only through right_hand_side(), energy() and limit_iterate(): it
// cannot leave one out.
struct StepProblem {
  const SpringNetwork& rest;            // V, E (#E by 2), masses m (#V, kg)
  const Eigen::VectorXd& rest_lengths;  // #E r (m)
  SolveSettings settings;               // k, dt, damping c, iterations, chebyshev
  const Eigen::MatrixXd& current;       // #V by 3 pᵗ (m)
  const Eigen::MatrixXd& previous;      // #V by 3 pᵗ⁻ᐞᵗ (m)
  const Eigen::MatrixXd& fext;          // #V by 3 f_ext (N): gravity and the forces
  const Eigen::MatrixXd& y;             // #V by 3 (N), as above
  SystemMatrix& system;                 // Q and its Cholesky factorization
  LocalStep& local_step;                // k Aᵀd(p) + y
  StepTerms& terms;                     // every term beyond the springs and the inertia
  StepContext context;                  // what the terms see of the step
  // The last step touched something (a collider, itself): the problem may change sharply
  // between iterations.
  bool touching = false;

  // The springs' and inertia's part of E (step_objective.h).
  StepObjectiveTerms objective_terms() const {
    return StepObjectiveTerms{rest.E,           rest_lengths, rest.m,   settings.k, settings.dt,
                              settings.damping, current,      previous, fext};
  }
  // rhs (#V by 3) = k Aᵀd(p) + y + every term's targets at p. If given, `springs` receives
  // Σ(‖pᵢ − pⱼ‖ − rᵢⱼ)² and `term_energy` every term's energy at p (J).
  void right_hand_side(const Eigen::MatrixXd& p, Eigen::MatrixXd& rhs, double* springs = nullptr,
                       double* term_energy = nullptr) const {
    local_step.apply(p, settings.k, y, rhs, springs);
    if (term_energy) *term_energy = 0.0;
    if (terms.in_solve() || term_energy) terms.add_targets(context, p, rhs, term_energy);
  }
  // E(p) (J); `gradient` (#V by 3, N), if given, receives ∇E(p).
  double energy(const Eigen::MatrixXd& p, Eigen::MatrixXd* gradient) const {
    return step_objective(objective_terms(), p, gradient) + terms.add_energy(context, p, gradient);
  }
  // After an update of the iterate: the terms may move p back within their bounds. Returns
  // whether any vertex moved.
  bool limit_iterate(Eigen::MatrixXd& p) const {
    return terms.in_solve() && terms.limit_iterate(context, p);
  }
};

// A method that minimizes a StepProblem with settings.iterations iterations from a first iterate.
// One is made per Simulation (see solver_registry.h), so it may keep buffers and state between
// steps; it must allocate nothing per iteration once warmed up by a step.
class StepSolver {
 public:
  virtual ~StepSolver() = default;
  // The name it is registered under ("local-global").
  virtual const char* name() const = 0;
  // Called when the solver is made and whenever settings.chebyshev (or another of its settings)
  // changes, with the problem of the step about to be taken; `p` holds that step's first
  // iterate and may be used as scratch. Nothing else of the state may change.
  virtual void prepare(const StepProblem& /*problem*/, Eigen::MatrixXd& /*p*/) {}
  // `p` (#V by 3) holds the first iterate and receives the last. Reports to `observers` once per
  // step and per iteration; fills timing's local_ms, global_ms and instruments_ms.
  virtual void solve(const StepProblem& problem, StepObservers& observers, Eigen::MatrixXd& p,
                     StepTiming& timing) = 0;
  // Its own numbers for the Simulation's accessors: the spectral radius its acceleration uses
  // (0 for a solver without one).
  virtual double spectral_radius() const { return 0.0; }
  // Whether it extrapolates its iterates (as prepared last): the terms then keep Q's diagonal
  // true to what they meet every step (StepContext::extrapolated).
  virtual bool extrapolates() const { return false; }
};

}  // namespace wobble

#endif

#ifndef WOBBLE_SIM_SOLVER_STEP_SOLVER_H
#define WOBBLE_SIM_SOLVER_STEP_SOLVER_H

#include <Eigen/Core>
#include <vector>

#include "sim/constraints/pins.h"
#include "sim/contact/solve_contact.h"
#include "sim/instruments/step_objective.h"
#include "sim/instruments/step_observer.h"
#include "sim/simulation_params.h"
#include "sim/solver/local_step.h"
#include "sim/solver/system_matrix.h"
#include "sim/spring_network.h"
#include "sim/step_terms.h"

namespace wobble {

// One time step's minimization problem, as the Simulation hands it to a solver: minimize over
// p (#V by 3, m) the step energy (see step_objective.h)
//   E(p) = ½k Σ(‖pᵢ−pⱼ‖−rᵢⱼ)² + (1 + cΔt)/(2Δt²)‖p − p̂‖²_M − pᵀf_ext + (w/2)‖Cp − C p_target‖²
// whose quadratic part is ½pᵀQp − pᵀy with
//   Q = k AᵀA + (1 + cΔt)M/Δt² + w CᵀC  (prefactored),
//   y = M((2 + cΔt)pᵗ − pᵗ⁻ᐞᵗ)/Δt² + f_ext + w CᵀC p_target,
// so that ∇E(p) = Q p − (k Aᵀd(p) + y), d(p) the local step's spring directions.
struct StepProblem {
  const SpringNetwork& rest;            // V, E (#E by 2), masses m (#V, kg)
  const Eigen::VectorXd& rest_lengths;  // #E r (m)
  const SimulationParams& params;       // k, dt, damping c, iterations, chebyshev, ...
  const Eigen::MatrixXd& current;       // #V by 3 pᵗ (m)
  const Eigen::MatrixXd& previous;      // #V by 3 pᵗ⁻ᐞᵗ (m)
  const Eigen::MatrixXd& fext;          // #V by 3 f_ext (N): gravity and the forces
  const Pins& pins;                     // C, w and p_target
  const Eigen::MatrixXd& y;             // #V by 3 (N), as above
  SystemMatrix& system;                 // Q and its Cholesky factorization
  LocalStep& local_step;                // rhs = k Aᵀd(p) + y
  // The constraints that project after the solve (colliders, self-collision), for a solver that
  // takes contact inside its iterations; local-global leaves them to the Simulation.
  const std::vector<PositionConstraint*>& constraints;
  // The last step touched a collider or itself: the problem may change sharply between
  // iterations.
  bool in_contact = false;
  // Contact inside the solve (solve_contact.h): its κ is on Q's diagonal for the vertices of its
  // set. Null, or an empty set, when no vertex is near a collider.
  const SolveContact* solve_contact = nullptr;
  const ColliderContact* colliders = nullptr;
  double time = 0.0;  // simulated time at the start of the step (s)

  bool has_solve_contact() const { return solve_contact && !solve_contact->empty(); }
  StepContext context() const {
    return StepContext{rest, current, previous, pins.flags(), params.dt, time};
  }

  // E(p) and ∇E(p) through step_objective(objective_terms(), p, &gradient).
  StepObjectiveTerms objective_terms() const {
    return StepObjectiveTerms{rest.E,    rest_lengths,   rest.m,         params.k,
                              params.dt, params.damping, current,        previous,
                              fext,      pins.flags(),   pins.targets(), Pins::weight};
  }
};

// A method that minimizes a StepProblem with params.iterations iterations from a first iterate.
// One is made per Simulation (see solver_registry.h), so it may keep buffers and state between
// steps; it must allocate nothing per iteration once warmed up by a step.
class StepSolver {
 public:
  virtual ~StepSolver() = default;
  // The name it is registered under ("local-global").
  virtual const char* name() const = 0;
  // Called when the solver is made and whenever params.chebyshev (or another of its settings)
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
};

}  // namespace wobble

#endif

#include "sim/solver/local_global_solver.h"

#include <vector>

#include "sim/instruments/stopwatch.h"

namespace wobble {

std::unique_ptr<StepSolver> make_local_global_solver(Eigen::Index vertices) {
  return std::make_unique<LocalGlobalSolver>(vertices);
}

LocalGlobalSolver::LocalGlobalSolver(Eigen::Index vertices)
    : rhs_(vertices, 3), solved_(vertices, 3), chebyshev_(vertices) {}

void LocalGlobalSolver::solve(const StepProblem& problem, StepObservers& observers,
                              Eigen::MatrixXd& p, StepTiming& timing) {
  const SolveSettings& settings = problem.settings;
  CholeskySolver& cholesky = problem.system.cholesky();
  const bool measuring = observers.wants_measures();
  // The solve of Q p = rhs gives Q p to rounding only in double precision (see IterateMeasure).
  const bool exact_solve = !cholesky.solves_in_single_precision();
  const StepObjectiveTerms terms = problem.objective_terms();
  double instruments_ms = 0.0;
  observers.begin_step(name(), settings.chebyshev);
  if (measuring) measure_.resize(p.rows());
  double springs = 0.0;  // Σ(‖pᵢ − pⱼ‖ − rᵢⱼ)² at the iterate, from the local step
  if (settings.chebyshev) chebyshev_.start(p);
  restart_iteration_ = 0;
  // Contact makes a step's problem change sharply from one iteration to the next; with ρ near 1
  // the extrapolation then runs away (a cloth falling on a sphere left it at 48 m/s). While the
  // last step touched a collider, an iteration whose update grew restarts the recurrence.
  const bool restart_on_growth = problem.touching;
  bool limited = false;  // the last iterate was moved after its solve
  double local_ms = 0.0, global_ms = 0.0;
  for (int iteration = 0; iteration < settings.iterations; ++iteration) {
    const Stopwatch local;
    double term_energy = 0.0;
    // The local step, and every term's targets (contact draws its vertices out of the colliders
    // and apart from the cloth's other layers; its weight is already in Q or its whole force here).
    problem.right_hand_side(p, rhs_, measuring ? &springs : nullptr,
                            measuring ? &term_energy : nullptr);
    local_ms += local.milliseconds();
    if (measuring) {
      const Stopwatch record;
      // The first iterate is a prediction; an accelerated or limited one is not the solve's
      // output.
      const bool plain_solve = iteration > 0 && !settings.chebyshev && !limited;
      const IterateMeasure::Result at =
          measure_.measure(terms, problem.system.Q(), p, rhs_, springs, plain_solve && exact_solve);
      observers.measured(at.energy + term_energy, at.gradient_norm);
      instruments_ms += record.milliseconds();
    }
    const Stopwatch global;
    // With acceleration every iteration but the last is accelerated; the last, plain, removes
    // what the acceleration leaves of the fast components (see chebyshev.h).
    if (settings.chebyshev && iteration + 1 < settings.iterations) {
      cholesky.solve(rhs_, solved_);
      accelerate(iteration, restart_on_growth, p);
    } else {
      cholesky.solve(rhs_, p);
    }
    global_ms += global.milliseconds();
    // Terms that bound how far a vertex may move (self-contact) take the iterate back within.
    const Stopwatch limit;
    limited = problem.limit_iterate(p);
    local_ms += limit.milliseconds();
    observers.iterated(iteration, p);
  }
  if (measuring) {
    // The last iterate, which no local step has seen yet.
    const Stopwatch record;
    double term_energy = 0.0;
    problem.right_hand_side(p, rhs_, &springs, &term_energy);
    // The last iteration is never accelerated.
    const IterateMeasure::Result at =
        measure_.measure(terms, problem.system.Q(), p, rhs_, springs, exact_solve && !limited);
    observers.measured(at.energy + term_energy, at.gradient_norm);
    instruments_ms += record.milliseconds();
  }
  timing.local_ms = local_ms;
  timing.global_ms = global_ms;
  timing.instruments_ms = instruments_ms;
}

void LocalGlobalSolver::accelerate(int iteration, bool restart_on_growth, Eigen::MatrixXd& p) {
  if (restart_on_growth) {
    const double update = (solved_ - p).squaredNorm();
    const bool grew = iteration > 0 && update > last_update_;
    last_update_ = update;
    if (grew) {
      chebyshev_.start(solved_);  // a plain iteration, and the recurrence starts again from it
      p.swap(solved_);
      restart_iteration_ = iteration;
      return;
    }
  }
  chebyshev_.accelerate(iteration - restart_iteration_, solved_, p);
}

void LocalGlobalSolver::prepare(const StepProblem& problem, Eigen::MatrixXd& p) {
  extrapolates_ = problem.settings.chebyshev;
  if (problem.settings.chebyshev && !calibrated_) calibrate(problem, p);
}

void LocalGlobalSolver::calibrate(const StepProblem& problem, Eigen::MatrixXd& p) {
  // The paper's calibration: plain iterations of one step, from the current state, watching the
  // updates shrink. Nothing of the state changes. The ratio of updates settles slowly on a soft
  // cloth: from iterations 20–40 it reads ρ ≈ 0.97 where the error shrinks by 0.985–0.99 per
  // iteration, and a ρ that low gives away most of the gain; from 50–100 it reads 0.98–0.99.
  std::vector<double> update_norms;
  for (int iteration = 0; iteration < chebyshev_calibration_iterations; ++iteration) {
    problem.right_hand_side(p, rhs_);
    problem.system.cholesky().solve(rhs_, solved_);
    update_norms.push_back((solved_ - p).norm());
    p.swap(solved_);
  }
  chebyshev_.set_spectral_radius(ChebyshevAcceleration::estimate_spectral_radius(update_norms));
  calibrated_ = true;
}

}  // namespace wobble

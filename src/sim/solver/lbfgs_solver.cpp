#include "sim/solver/lbfgs_solver.h"

#include <cmath>

#include "sim/instruments/stopwatch.h"

namespace wobble {

namespace {

// Σ aᵢⱼ bᵢⱼ over #V by 3 arrays.
double dot(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a.array() * b.array()).sum();
}

}  // namespace

std::unique_ptr<StepSolver> make_lbfgs_solver(Eigen::Index vertices) {
  return std::make_unique<LbfgsSolver>(vertices);
}

LbfgsSolver::LbfgsSolver(Eigen::Index vertices)
    : gradient_(vertices, 3),
      direction_(vertices, 3),
      trial_(vertices, 3),
      trial_gradient_(vertices, 3),
      work_(vertices, 3),
      s_(history, Eigen::MatrixXd(vertices, 3)),
      y_(history, Eigen::MatrixXd(vertices, 3)),
      rho_(history, 0.0),
      alpha_(history, 0.0) {}

double LbfgsSolver::evaluate(const StepProblem& problem, const Eigen::MatrixXd& p,
                             Eigen::MatrixXd& gradient) const {
  return problem.energy(p, &gradient);
}

void LbfgsSolver::find_direction(const StepProblem& problem) {
  // The two-loop recursion: q = g, newest pair to oldest; r = Q⁻¹q; oldest to newest.
  work_ = gradient_;
  for (int n = 0; n < stored_; ++n) {
    const int i = (newest_ - n + history) % history;
    alpha_[i] = rho_[i] * dot(s_[i], work_);
    work_ -= alpha_[i] * y_[i];
  }
  problem.system.cholesky().solve(work_, direction_);
  for (int n = stored_ - 1; n >= 0; --n) {
    const int i = (newest_ - n + history) % history;
    const double beta = rho_[i] * dot(y_[i], direction_);
    direction_ += (alpha_[i] - beta) * s_[i];
  }
  direction_ = -direction_;
}

void LbfgsSolver::solve(const StepProblem& problem, StepObservers& observers, Eigen::MatrixXd& p,
                        StepTiming& timing) {
  observers.begin_step(name(), false);
  stored_ = 0;
  newest_ = -1;
  last_iterations_ = 0;
  last_extra_evaluations_ = 0;
  double local_ms = 0.0, global_ms = 0.0;
  Stopwatch local;
  double energy = evaluate(problem, p, gradient_);
  local_ms += local.milliseconds();
  observers.measured(energy, gradient_.norm());
  for (int iteration = 0; iteration < problem.settings.iterations; ++iteration) {
    const Stopwatch global;
    find_direction(problem);
    double slope = dot(gradient_, direction_);
    if (!(slope < 0.0)) {
      // Not a descent direction (the pairs no longer describe E here): start the history again
      // from Q alone, whose inverse is positive definite.
      stored_ = 0;
      find_direction(problem);
      slope = dot(gradient_, direction_);
    }
    global_ms += global.milliseconds();
    const Stopwatch search;
    double alpha = 1.0, trial_energy = 0.0;
    bool lowered = false;
    for (int halving = 0; halving <= max_halvings && slope < 0.0; ++halving) {
      trial_ = p + alpha * direction_;
      trial_energy = evaluate(problem, trial_, trial_gradient_);
      if (halving > 0) ++last_extra_evaluations_;
      if (trial_energy <= energy + 1e-4 * alpha * slope) {
        lowered = true;
        break;
      }
      alpha *= 0.5;
    }
    local_ms += search.milliseconds();
    if (!lowered) {
      // No lower energy along the direction: the iterate is a minimum to rounding. Later
      // iterations would repeat this one; each still reports, so a trace has its full length.
      for (int rest = iteration; rest < problem.settings.iterations; ++rest) {
        observers.measured(energy, gradient_.norm());
        observers.iterated(rest, p);
      }
      break;
    }
    // The new pair, kept only when its curvature sᵀy is positive (E is convex along it).
    const Stopwatch pair;
    const int slot = (newest_ + 1) % history;
    s_[slot] = trial_ - p;
    y_[slot] = trial_gradient_ - gradient_;
    const double curvature = dot(s_[slot], y_[slot]);
    if (curvature > 1e-12 * std::sqrt(s_[slot].squaredNorm() * y_[slot].squaredNorm())) {
      rho_[slot] = 1.0 / curvature;
      newest_ = slot;
      if (stored_ < history) ++stored_;
    }
    p.swap(trial_);
    gradient_.swap(trial_gradient_);
    energy = trial_energy;
    ++last_iterations_;
    global_ms += pair.milliseconds();
    // Terms that bound how far a vertex may move (self-contact) take the iterate back within;
    // the energy and gradient are then those of where it is, and the pairs start again.
    const Stopwatch limit;
    if (problem.limit_iterate(p)) {
      energy = evaluate(problem, p, gradient_);
      stored_ = 0;
    }
    local_ms += limit.milliseconds();
    observers.measured(energy, gradient_.norm());
    observers.iterated(iteration, p);
  }
  timing.local_ms = local_ms;
  timing.global_ms = global_ms;
  timing.instruments_ms = 0.0;
}

}  // namespace wobble

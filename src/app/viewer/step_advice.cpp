#include "app/viewer/step_advice.h"

#include <cstdio>
#include <limits>

namespace wobble {

namespace {

// Above this k Δt²/m the springs dominate the step so much that 50 plain iterations leave it far
// from converged (the cloth at k = 10⁶: about 10⁴).
constexpr double stiff_ratio = 1e3;

}  // namespace

std::string describe_failed_step(const FailedStep& failed) {
  std::string what = failed.status == StepStatus::not_finite
                         ? "a position became non-finite"
                         : "a vertex moved more than 100 times the shape's size";
  what = "Paused at step " + std::to_string(failed.step) + ": " + what + ", so the step was " +
         "rolled back; ";
  if (failed.dragging) {
    return what +
           "the held vertex was pulled too far in one step: drag more slowly, or raise the "
           "iterations.";
  }
  if (failed.step == 1 && failed.initial_velocity) {
    return what +
           "at the first step that comes from the scene's initial velocity: lower it, or "
           "dt.";
  }
  if (failed.stiffness_ratio > stiff_ratio) {
    char ratio[32];
    std::snprintf(ratio, sizeof(ratio), "%.2g", failed.stiffness_ratio);
    return what + "the springs are far stiffer than the masses' inertia (k dt^2/m = " + ratio +
           "): lower k or dt, or raise the iterations or turn on Chebyshev.";
  }
  return what + "try a smaller dt or more iterations.";
}

double stiffness_ratio(const Simulation& simulation) {
  double lightest = std::numeric_limits<double>::infinity();
  const Eigen::VectorXd& m = simulation.rest().m;
  for (Eigen::Index i = 0; i < m.size(); ++i) {
    if (m(i) > 0.0 && m(i) < lightest) lightest = m(i);
  }
  if (!(lightest < std::numeric_limits<double>::infinity())) return 0.0;
  const SimulationParams& params = simulation.params();
  return params.k * params.dt * params.dt / lightest;
}

}  // namespace wobble

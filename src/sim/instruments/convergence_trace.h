#ifndef WOBBLE_SIM_INSTRUMENTS_CONVERGENCE_TRACE_H
#define WOBBLE_SIM_INSTRUMENTS_CONVERGENCE_TRACE_H

#include <vector>

namespace wobble {

// How one step's iterations converged (local-global, L-BFGS): the step objective (step_objective.h)
// and the norm of its gradient at each iterate. Entry 0 is the first iterate, before any iteration;
// entry i is the iterate after i iterations (with Chebyshev on, the accelerated iterate).
struct ConvergenceTrace {
  std::vector<double> energy;           // J
  std::vector<double> gradient_norm;    // N, ‖∇‖ over all 3#V components
  bool chebyshev = false;               // the iterations were accelerated
  const char* solver = "local-global";  // the registered name of the solver that took the step
  // N: the gradient the step's inertia alone would have with every vertex a mean spring rest
  // length r̄ off its minimum (along one axis), ‖m‖₂ r̄ / Δt²: a leftover gradient far below it
  // moves the vertices by far less than a spring's length. 0 when not given.
  double force_scale = 0.0;

  int iterations() const { return energy.empty() ? 0 : static_cast<int>(energy.size()) - 1; }
  // ‖∇‖ after the last iteration over the step's scale: the larger of ‖∇‖ at the start of the
  // step (the first iterate's or the first iteration's) and force_scale. How far the step got
  // towards its minimum (1: nowhere): a step that barely moves (a cloth at rest) starts with
  // almost no gradient, and its leftover is then measured against what would move the vertices
  // by a spring's length instead of against that. 0 for an empty trace or a step that started at
  // its minimum with no scale.
  double gradient_reduction() const;
};

// How converged a step looks to a class: the gradient's reduction over the step.
enum class Convergence {
  converged,  // reduced at least a thousandfold (or the step started at its minimum)
  partial,    // reduced between tenfold and a thousandfold
  far,        // reduced less than tenfold: the positions are far from the step's minimum
};
Convergence classify(const ConvergenceTrace& trace);

}  // namespace wobble

#endif

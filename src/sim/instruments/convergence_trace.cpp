#include "convergence_trace.h"

#include <algorithm>

namespace wobble {

double ConvergenceTrace::gradient_reduction() const {
  if (gradient_norm.empty()) return 0.0;
  // The first iterate is a prediction: from rest its gradient is only the unbalanced external
  // force, and the first iteration, which lowers the energy, can raise the gradient tenfold.
  // The start of the step is the larger of the two.
  // At rest the start's gradient is near nothing, and a leftover far too small to see would read
  // as far from converged: the inertia's scale over a spring's length is the scale then.
  const double start = std::max(
      gradient_norm.size() > 1 ? std::max(gradient_norm[0], gradient_norm[1]) : gradient_norm[0],
      force_scale);
  if (!(start > 0.0)) return 0.0;
  return gradient_norm.back() / start;
}

Convergence classify(const ConvergenceTrace& trace) {
  const double reduction = trace.gradient_reduction();
  if (reduction <= 1e-3) return Convergence::converged;
  if (reduction <= 1e-1) return Convergence::partial;
  return Convergence::far;
}

}  // namespace wobble

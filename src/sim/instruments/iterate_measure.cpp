#include "iterate_measure.h"

#include <cmath>

namespace wobble {

void IterateMeasure::resize(Eigen::Index vertices) {
  gradient_.resize(vertices, 3);
  previous_rhs_.resize(vertices, 3);
}

IterateMeasure::Result IterateMeasure::measure(const StepObjectiveTerms& terms,
                                               const Eigen::SparseMatrix<double>& Q,
                                               const Eigen::MatrixXd& p, const Eigen::MatrixXd& rhs,
                                               double springs, bool plain_solve) {
  double squared = 0.0;
  if (plain_solve) {
    // One pass: the difference, its norm, and the right-hand side kept for the next iterate.
    double* previous = previous_rhs_.data();
    const double* current = rhs.data();
    for (Eigen::Index s = 0; s < rhs.size(); ++s) {
      const double difference = previous[s] - current[s];
      squared += difference * difference;
      previous[s] = current[s];
    }
  } else {
    gradient_.noalias() = Q * p;
    gradient_ -= rhs;
    squared = gradient_.squaredNorm();
    previous_rhs_ = rhs;
  }
  Result result;
  result.gradient_norm = std::sqrt(squared);
  result.energy = step_objective_vertex_terms(terms, p) + 0.5 * terms.k * springs;
  return result;
}

}  // namespace wobble

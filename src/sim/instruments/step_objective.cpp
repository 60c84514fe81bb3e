#include "step_objective.h"

#include <cmath>

namespace wobble {

double step_objective(const StepObjectiveTerms& terms, const Eigen::MatrixXd& p,
                      Eigen::MatrixXd* gradient) {
  const Eigen::Index n = p.rows();
  if (gradient != nullptr) {
    if (gradient->rows() != n || gradient->cols() != 3) gradient->resize(n, 3);
    gradient->setZero();
  }
  double springs = 0.0;
  for (Eigen::Index e = 0; e < terms.E.rows(); ++e) {
    const int i = terms.E(e, 0), j = terms.E(e, 1);
    const Eigen::Vector3d between = (p.row(i) - p.row(j)).transpose();
    const double length = between.norm();
    const double stretch = length - terms.r(e);
    springs += stretch * stretch;
    // A spring of zero length has no direction; its force is taken as zero there, as the local
    // step's projection is arbitrary there too.
    if (gradient != nullptr && length > 0.0) {
      const Eigen::RowVector3d force = (terms.k * stretch / length) * between.transpose();
      gradient->row(i) += force;
      gradient->row(j) -= force;
    }
  }
  if (gradient != nullptr) {
    // The vertex terms' gradient: (1 + cΔt)/Δt² M(p − p̂) − f_ext.
    const double cdt = terms.damping * terms.dt;
    const double inertia_weight = (1.0 + cdt) / (terms.dt * terms.dt);
    for (int c = 0; c < 3; ++c) {
      for (Eigen::Index i = 0; i < n; ++i) {
        const double predicted =
            ((2.0 + cdt) * terms.current(i, c) - terms.previous(i, c)) / (1.0 + cdt);
        (*gradient)(i, c) += inertia_weight * terms.m(i) * (p(i, c) - predicted) - terms.fext(i, c);
      }
    }
  }
  return 0.5 * terms.k * springs + step_objective_vertex_terms(terms, p);
}

double step_objective_vertex_terms(const StepObjectiveTerms& terms, const Eigen::MatrixXd& p) {
  const double cdt = terms.damping * terms.dt;
  double inertia = 0.0, work = 0.0;
  for (int c = 0; c < 3; ++c) {
    // Column by column: the matrices are stored that way.
    const double* position = p.col(c).data();
    const double* current = terms.current.col(c).data();
    const double* previous = terms.previous.col(c).data();
    const double* force = terms.fext.col(c).data();
    for (Eigen::Index i = 0; i < p.rows(); ++i) {
      const double away = position[i] - ((2.0 + cdt) * current[i] - previous[i]) / (1.0 + cdt);
      inertia += terms.m(i) * away * away;
      work += position[i] * force[i];
    }
  }
  return 0.5 * (1.0 + cdt) / (terms.dt * terms.dt) * inertia - work;
}

}  // namespace wobble

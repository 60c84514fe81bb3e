#include "local_step.h"

#include <cmath>

namespace wobble {

LocalStep::LocalStep(const Eigen::MatrixXi& E, const Eigen::VectorXd& r, const Eigen::MatrixXd& V,
                     WorkerPool& pool)
    : E_(E), r_(r), rest_direction_(E.rows(), 3), d_(E.rows(), 3), pool_(&pool) {
  const Eigen::Index n = V.rows();
  for (Eigen::Index e = 0; e < E.rows(); ++e) {
    rest_direction_.row(e) = V.row(E(e, 0)) - V.row(E(e, 1));
  }
  incident_start_.assign(n + 1, 0);
  for (Eigen::Index e = 0; e < E.rows(); ++e) {
    ++incident_start_[E(e, 0) + 1];
    ++incident_start_[E(e, 1) + 1];
  }
  for (Eigen::Index i = 0; i < n; ++i)
    incident_start_[i + 1] += incident_start_[i];
  incident_.resize(2 * E.rows());
  std::vector<int> next(incident_start_.begin(), incident_start_.end() - 1);
  for (Eigen::Index e = 0; e < E.rows(); ++e) {
    incident_[next[E(e, 0)]++] = static_cast<int>(e);
    incident_[next[E(e, 1)]++] = ~static_cast<int>(e);
  }
}

void LocalStep::apply(const Eigen::MatrixXd& p, double k, const Eigen::MatrixXd& y,
                      Eigen::MatrixXd& rhs) {
  const Eigen::Index springs = E_.rows();
  const Eigen::Index n = p.rows();
  const auto directions = [&](Eigen::Index begin, Eigen::Index end) {
    for (Eigen::Index e = begin; e < end; ++e) {
      const int i = E_(e, 0), j = E_(e, 1);
      const double dx = p(i, 0) - p(j, 0), dy = p(i, 1) - p(j, 1), dz = p(i, 2) - p(j, 2);
      const double length = std::sqrt(dx * dx + dy * dy + dz * dz);
      if (length > 0.0) {
        const double scale = k * r_(e) / length;
        d_(e, 0) = scale * dx;
        d_(e, 1) = scale * dy;
        d_(e, 2) = scale * dz;
      } else {
        // Coincident ends have no direction: fall back on the rest direction, which pushes them
        // apart along the line they started on.
        d_.row(e) = k * rest_direction_.row(e);
      }
    }
  };
  const auto gather = [&](Eigen::Index begin, Eigen::Index end) {
    for (Eigen::Index i = begin; i < end; ++i) {
      double x = y(i, 0), yy = y(i, 1), z = y(i, 2);
      for (int s = incident_start_[i]; s < incident_start_[i + 1]; ++s) {
        const int entry = incident_[s];
        const int e = entry >= 0 ? entry : ~entry;
        const double sign = entry >= 0 ? 1.0 : -1.0;
        x += sign * d_(e, 0);
        yy += sign * d_(e, 1);
        z += sign * d_(e, 2);
      }
      rhs(i, 0) = x;
      rhs(i, 1) = yy;
      rhs(i, 2) = z;
    }
  };
  // A small network is done before a helper could wake up to help.
  if (springs < min_springs_for_threads || pool_->threads() == 1) {
    directions(0, springs);
    gather(0, n);
    return;
  }
  // Several pieces a thread, so that the caller takes over the pieces of a helper that has no
  // core to run on, instead of waiting for it.
  const int pieces = pieces_per_thread * pool_->threads();
  auto spring_piece = [&](int piece) {
    directions(springs * piece / pieces, springs * (piece + 1) / pieces);
  };
  pool_->run(pieces, spring_piece);
  auto vertex_piece = [&](int piece) { gather(n * piece / pieces, n * (piece + 1) / pieces); };
  pool_->run(pieces, vertex_piece);
}

}  // namespace wobble

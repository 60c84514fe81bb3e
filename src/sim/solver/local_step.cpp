#include "local_step.h"

#include <algorithm>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace wobble {

LocalStep::LocalStep(const Eigen::MatrixXi& E, const Eigen::VectorXd& r, const Eigen::MatrixXd& V,
                     WorkerPool& pool)
    : E_(E),
      r_(r),
      rest_direction_(E.rows(), 3),
      d_(E.rows(), 3),
      lengths_(E.rows()),
      pool_(&pool) {
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
                      Eigen::MatrixXd& rhs, double* spring_energy) {
  const Eigen::Index springs = E_.rows();
  const bool keep_lengths = spring_energy != nullptr;
  const Eigen::Index n = p.rows();
  const auto directions = [&](Eigen::Index begin, Eigen::Index end) {
    // Coincident ends have no direction: fall back on the rest direction, which pushes them
    // apart along the line they started on.
    const auto store = [&](Eigen::Index e, double length, double x, double y, double z) {
      double* d = d_.data() + 3 * e;
      if (keep_lengths) lengths_(e) = length;
      if (length > 0.0) {
        d[0] = x;
        d[1] = y;
        d[2] = z;
      } else {
        d_.row(e) = k * rest_direction_.row(e);
      }
    };
#if defined(__SSE2__)
    // Two springs at a time: the square roots and divisions, which bound this loop, go twice as
    // fast. Every spring, the last of an odd count too (then computed in both lanes), takes this
    // path, so the result does not depend on where the threads' pieces begin.
    const __m128d k_lanes = _mm_set1_pd(k);
    for (Eigen::Index e = begin; e < end; e += 2) {
      const Eigen::Index f = std::min(e + 1, end - 1);
      const int i0 = E_(e, 0), j0 = E_(e, 1), i1 = E_(f, 0), j1 = E_(f, 1);
      const __m128d dx = _mm_sub_pd(_mm_set_pd(p(i1, 0), p(i0, 0)), _mm_set_pd(p(j1, 0), p(j0, 0)));
      const __m128d dy = _mm_sub_pd(_mm_set_pd(p(i1, 1), p(i0, 1)), _mm_set_pd(p(j1, 1), p(j0, 1)));
      const __m128d dz = _mm_sub_pd(_mm_set_pd(p(i1, 2), p(i0, 2)), _mm_set_pd(p(j1, 2), p(j0, 2)));
      const __m128d length = _mm_sqrt_pd(
          _mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)), _mm_mul_pd(dz, dz)));
      const __m128d scale = _mm_div_pd(_mm_mul_pd(k_lanes, _mm_set_pd(r_(f), r_(e))), length);
      alignas(16) double x[2], y[2], z[2], l[2];
      _mm_store_pd(x, _mm_mul_pd(scale, dx));
      _mm_store_pd(y, _mm_mul_pd(scale, dy));
      _mm_store_pd(z, _mm_mul_pd(scale, dz));
      _mm_store_pd(l, length);
      store(e, l[0], x[0], y[0], z[0]);
      if (f != e) store(f, l[1], x[1], y[1], z[1]);
    }
#else
    for (Eigen::Index e = begin; e < end; ++e) {
      const int i = E_(e, 0), j = E_(e, 1);
      const double dx = p(i, 0) - p(j, 0), dy = p(i, 1) - p(j, 1), dz = p(i, 2) - p(j, 2);
      const double length = std::sqrt(dx * dx + dy * dy + dz * dz);
      const double scale = k * r_(e) / length;
      store(e, length, scale * dx, scale * dy, scale * dz);
    }
#endif
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
  // Summed here, in one fixed order, so that the energy does not depend on the threads.
  const auto sum_energy = [&] {
    if (keep_lengths) *spring_energy = (lengths_ - r_).squaredNorm();
  };
  // A small network is done before a helper could wake up to help.
  if (springs < min_springs_for_threads || pool_->threads() == 1) {
    directions(0, springs);
    gather(0, n);
    sum_energy();
    return;
  }
  // Several pieces a thread, so that the caller takes over the pieces of a helper that has no
  // core to run on, instead of waiting for it.
  const int pieces = pieces_per_thread * pool_->threads();
  auto spring_piece = [&](int piece) {
    directions(springs * piece / pieces, springs * (piece + 1) / pieces);
  };
  pool_->run(pieces, spring_piece, &spring_payoff_);
  auto vertex_piece = [&](int piece) { gather(n * piece / pieces, n * (piece + 1) / pieces); };
  pool_->run(pieces, vertex_piece, &vertex_payoff_);
  sum_energy();
}

}  // namespace wobble

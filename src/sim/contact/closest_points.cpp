#include "sim/contact/closest_points.h"

#include <algorithm>

namespace wobble {

Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  // By the region of the triangle's plane that p projects into: the three corners, the three
  // edges, the inside.
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {1.0, 0.0, 0.0};
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {0.0, 1.0, 0.0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double t = d1 / (d1 - d3);
    return {1.0 - t, t, 0.0};
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {0.0, 0.0, 1.0};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double t = d2 / (d2 - d6);
    return {1.0 - t, 0.0, t};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0.0, 1.0 - t, t};
  }
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) {
    // Zero area: the closest of its three edges.
    Eigen::Vector3d best(1.0, 0.0, 0.0);
    double best_distance = (p - a).squaredNorm();
    const Eigen::Vector3d corners[3] = {a, b, c};
    for (int e = 0; e < 3; ++e) {
      const Eigen::Vector3d& from = corners[e];
      const Eigen::Vector3d along = corners[(e + 1) % 3] - from;
      const double length2 = along.squaredNorm();
      const double t = length2 > 0.0 ? std::clamp((p - from).dot(along) / length2, 0.0, 1.0) : 0.0;
      const double distance = (p - from - t * along).squaredNorm();
      if (distance < best_distance) {
        best_distance = distance;
        best.setZero();
        best(e) = 1.0 - t;
        best((e + 1) % 3) = t;
      }
    }
    return best;
  }
  return {va / sum, vb / sum, vc / sum};
}

Eigen::Vector2d closest_on_segments(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                    const Eigen::Vector3d& q0, const Eigen::Vector3d& q1) {
  const Eigen::Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  if (!(a > 0.0) && !(e > 0.0)) return {0.0, 0.0};
  if (!(a > 0.0)) return {0.0, std::clamp(f / e, 0.0, 1.0)};
  const double c = d1.dot(r);
  if (!(e > 0.0)) return {std::clamp(-c / a, 0.0, 1.0), 0.0};
  // Minimize ‖r + s d1 − u d2‖² over the square: the unconstrained s for the lines, clamped,
  // then the u it gives, clamped, and s again for a clamped u.
  const double b = d1.dot(d2), denominator = a * e - b * b;
  double s = denominator > 0.0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
  double u = (b * s + f) / e;
  if (u < 0.0) {
    u = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (u > 1.0) {
    u = 1.0;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  return {s, u};
}

}  // namespace wobble

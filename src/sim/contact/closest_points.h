#ifndef WOBBLE_SIM_CONTACT_CLOSEST_POINTS_H
#define WOBBLE_SIM_CONTACT_CLOSEST_POINTS_H

#include <Eigen/Core>

namespace wobble {

// The point of triangle abc closest to p, as barycentric coordinates (α_a, α_b, α_c) ≥ 0 summing
// to 1. A degenerate triangle (zero area) gives its closest edge or corner point.
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// The closest points of segments p0p1 and q0q1, as parameters (s, u) in [0, 1]²: the points are
// p0 + s(p1 − p0) and q0 + u(q1 − q0). Parallel segments give one of the closest pairs.
Eigen::Vector2d closest_on_segments(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                    const Eigen::Vector3d& q0, const Eigen::Vector3d& q1);

}  // namespace wobble

#endif

#include "sim/contact/self_collision.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <utility>

#include "sim/contact/closest_points.h"
#include "sim/input_error.h"
#include "sim/value_limits.h"

namespace wobble {

namespace {

using Clock = std::chrono::steady_clock;

double milliseconds_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

Eigen::Vector3d row(const Eigen::MatrixXd& m, int i) {
  return Eigen::Vector3d(m(i, 0), m(i, 1), m(i, 2));
}

// Gauss-Seidel sweeps stop once no pair is short of the thickness by more than this fraction.
constexpr double settled_fraction = 1e-3;
constexpr int max_sweeps = 16;

}  // namespace

void validate_self_collision(const SelfCollisionParams& params) {
  if (!limits::self_collision_thickness.contains(params.thickness)) {
    throw InputError("self-collision thickness: expected " +
                     expected_in(limits::self_collision_thickness) + ", got " +
                     limit_text(params.thickness));
  }
}

SelfCollision::SelfCollision(const SpringNetwork& rest, const SelfCollisionParams& params)
    : params_(params), rest_(rest.V), triangles_(rest.F) {
  std::vector<char> on_surface(rest.V.rows(), 0);
  std::map<std::pair<int, int>, int> edge_ids;
  std::vector<std::pair<int, int>> edges;
  double edge_sum = 0.0;
  for (Eigen::Index t = 0; t < triangles_.rows(); ++t) {
    for (int c = 0; c < 3; ++c) {
      const int i = triangles_(t, c), j = triangles_(t, (c + 1) % 3);
      on_surface[i] = 1;
      const std::pair<int, int> key(std::min(i, j), std::max(i, j));
      if (edge_ids.emplace(key, static_cast<int>(edges.size())).second) {
        edges.push_back(key);
        edge_sum += (row(rest_, i) - row(rest_, j)).norm();
      }
    }
  }
  edges_.resize(static_cast<Eigen::Index>(edges.size()), 2);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    edges_(e, 0) = edges[e].first;
    edges_(e, 1) = edges[e].second;
  }
  for (Eigen::Index i = 0; i < rest.V.rows(); ++i) {
    if (on_surface[i]) surface_vertices_.push_back(static_cast<int>(i));
  }
  // Cells about an edge long: each swept box covers a few cells, each cell holds a few boxes.
  const double mean_edge = edges.empty() ? 1.0 : edge_sum / static_cast<double>(edges.size());
  const double cell = mean_edge > 0.0 ? mean_edge : 1.0;
  triangle_grid_ = SpatialGrid(cell);
  edge_grid_ = SpatialGrid(cell);
  in_contact_.assign(rest.V.rows(), 0);
  seen_triangle_.assign(triangles_.rows(), -1);
}

void SelfCollision::clear() {
  std::fill(in_contact_.begin(), in_contact_.end(), 0);
  contact_count_ = 0;
  pair_count_ = 0;
  pairs_.clear();
}

void SelfCollision::sweep_boxes(const Eigen::MatrixXd& current, const Eigen::MatrixXd& next) {
  // Two features closer than the thickness have boxes closer than that along every axis: each
  // box grows by half of it.
  const double grow = 0.5 * params_.thickness;
  const auto swept = [&](const int* vertices, int count) {
    Eigen::AlignedBox3d box;
    for (int k = 0; k < count; ++k) {
      box.extend(row(current, vertices[k]));
      box.extend(row(next, vertices[k]));
    }
    box.min().array() -= grow;
    box.max().array() += grow;
    return box;
  };
  triangle_boxes_.resize(triangles_.rows());
  for (Eigen::Index t = 0; t < triangles_.rows(); ++t) {
    const int corners[3] = {triangles_(t, 0), triangles_(t, 1), triangles_(t, 2)};
    triangle_boxes_[t] = swept(corners, 3);
  }
  edge_boxes_.resize(edges_.rows());
  for (Eigen::Index e = 0; e < edges_.rows(); ++e) {
    const int ends[2] = {edges_(e, 0), edges_(e, 1)};
    edge_boxes_[e] = swept(ends, 2);
  }
}

void SelfCollision::keep_if_close(Pair pair, int first_size, const Eigen::MatrixXd& current,
                                  const Eigen::MatrixXd& next) {
  const double h = params_.thickness;
  // The gap between the pair's two points at the start, and how much closer they can come: the
  // distance between the two features changes by at most the largest motion of a vertex of one
  // relative to the first vertex, plus the same for the other.
  Eigen::Vector3d start = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k)
    start += pair.beta[k] * row(current, pair.vertex[k]);
  const double distance = start.norm();
  const Eigen::Vector3d reference = row(next, pair.vertex[0]) - row(current, pair.vertex[0]);
  double closing_first = 0.0, closing_second = 0.0;
  for (int k = 1; k < 4; ++k) {
    const double moved =
        (row(next, pair.vertex[k]) - row(current, pair.vertex[k]) - reference).norm();
    double& closing = k < first_size ? closing_first : closing_second;
    closing = std::max(closing, moved);
  }
  if (distance - closing_first - closing_second >= h) return;
  // Pairs this close in the rest shape are a fine mesh's neighbours, not two layers.
  Eigen::Vector3d rest_gap = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k)
    rest_gap += pair.beta[k] * row(rest_, pair.vertex[k]);
  if (rest_gap.norm() < h) return;
  if (distance > 1e-9 * h) {
    pair.normal = start / distance;
  } else {
    // Touching at the start (nothing kept them apart): the normal of the two features' plane,
    // on the side the pair ends on.
    pair.normal = (row(current, pair.vertex[1]) - row(current, pair.vertex[0]))
                      .cross(row(current, pair.vertex[3]) - row(current, pair.vertex[2]));
    if (!(pair.normal.squaredNorm() > 0.0)) return;
    pair.normal.normalize();
    Eigen::Vector3d end = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k)
      end += pair.beta[k] * row(next, pair.vertex[k]);
    if (end.dot(pair.normal) < 0.0) pair.normal = -pair.normal;
  }
  pairs_.push_back(pair);
}

void SelfCollision::find_vertex_triangle_pairs(const Eigen::MatrixXd& current,
                                               const Eigen::MatrixXd& next) {
  std::fill(seen_triangle_.begin(), seen_triangle_.end(), -1);
  for (const int v : surface_vertices_) {
    Eigen::AlignedBox3d box(row(current, v));
    box.extend(row(next, v));
    box.min().array() -= 0.5 * params_.thickness;
    box.max().array() += 0.5 * params_.thickness;
    const Eigen::Vector3d v0 = row(current, v);
    triangle_grid_.for_each_candidate(box, [&](int t) {
      if (seen_triangle_[t] == v) return;
      seen_triangle_[t] = v;
      const int a = triangles_(t, 0), b = triangles_(t, 1), c = triangles_(t, 2);
      if (v == a || v == b || v == c || !box.intersects(triangle_boxes_[t])) return;
      const Eigen::Vector3d alpha =
          closest_on_triangle(v0, row(current, a), row(current, b), row(current, c));
      keep_if_close(Pair{{v, a, b, c}, {1.0, -alpha(0), -alpha(1), -alpha(2)}, {}, 0.0}, 1, current,
                    next);
    });
  }
}

void SelfCollision::find_edge_edge_pairs(const Eigen::MatrixXd& current,
                                         const Eigen::MatrixXd& next) {
  edge_grid_.for_each_overlapping_pair([&](int e, int f) {
    const int p0 = edges_(e, 0), p1 = edges_(e, 1), q0 = edges_(f, 0), q1 = edges_(f, 1);
    if (q0 == p0 || q0 == p1 || q1 == p0 || q1 == p1) return;
    const Eigen::Vector2d su =
        closest_on_segments(row(current, p0), row(current, p1), row(current, q0), row(current, q1));
    keep_if_close(Pair{{p0, p1, q0, q1}, {1.0 - su(0), su(0), -(1.0 - su(1)), -su(1)}, {}, 0.0}, 2,
                  current, next);
  });
}

double SelfCollision::separate(const Eigen::VectorXd& inverse_mass, Eigen::MatrixXd& next) {
  const double h = params_.thickness;
  double worst = 0.0;
  for (Pair& pair : pairs_) {
    double gap = 0.0, weight = 0.0;
    for (int k = 0; k < 4; ++k) {
      const int i = pair.vertex[k];
      gap += pair.beta[k] * (next(i, 0) * pair.normal(0) + next(i, 1) * pair.normal(1) +
                             next(i, 2) * pair.normal(2));
      weight += pair.beta[k] * pair.beta[k] * inverse_mass(i);
    }
    const double violation = h - gap;
    if (!(violation > 0.0) || !(weight > 0.0)) continue;  // kept apart, or nothing can move
    // No vertex moves farther than the violation: when the only vertex free to move has a small
    // weight βₖ (a triangle's corner far from the contact, the others pinned), the full
    // correction would throw it violation/βₖ away.
    double largest = 0.0;
    for (int k = 0; k < 4; ++k)
      largest = std::max(largest, inverse_mass(pair.vertex[k]) * std::abs(pair.beta[k]));
    const double lambda = std::min(violation / weight, violation / largest);
    for (int k = 0; k < 4; ++k) {
      const int i = pair.vertex[k];
      next.row(i) += (inverse_mass(i) * pair.beta[k] * lambda) * pair.normal.transpose();
    }
    pair.lambda += lambda;
    worst = std::max(worst, violation);
  }
  return worst;
}

void SelfCollision::apply_friction(const Eigen::MatrixXd& current,
                                   const Eigen::VectorXd& inverse_mass, double friction,
                                   Eigen::MatrixXd& next) {
  for (const Pair& pair : pairs_) {
    if (!(pair.lambda > 0.0)) continue;
    // The pair's relative motion over the step, less its normal part.
    Eigen::Vector3d relative = Eigen::Vector3d::Zero();
    double weight = 0.0;
    for (int k = 0; k < 4; ++k) {
      const int i = pair.vertex[k];
      relative += pair.beta[k] * (row(next, i) - row(current, i));
      weight += pair.beta[k] * pair.beta[k] * inverse_mass(i);
    }
    const Eigen::Vector3d tangential = relative - relative.dot(pair.normal) * pair.normal;
    const double slide = tangential.norm();
    if (!(slide > 0.0) || !(weight > 0.0)) continue;
    // Coulomb: the slide shrinks by μ times the depth the pair was pushed out, at most to rest.
    const double undone = std::min(slide, friction * pair.lambda * weight);
    const Eigen::Vector3d direction = tangential / slide;
    for (int k = 0; k < 4; ++k) {
      const int i = pair.vertex[k];
      next.row(i) -= (inverse_mass(i) * pair.beta[k] * undone / weight) * direction.transpose();
    }
  }
}

void SelfCollision::project(const Eigen::MatrixXd& current, const Eigen::VectorXd& inverse_mass,
                            double friction, Eigen::MatrixXd& next) {
  clear();
  const auto detection_start = Clock::now();
  sweep_boxes(current, next);
  triangle_grid_.build(triangle_boxes_);
  edge_grid_.build(edge_boxes_);
  find_vertex_triangle_pairs(current, next);
  find_edge_edge_pairs(current, next);
  detection_ms_ = milliseconds_since(detection_start);

  const auto response_start = Clock::now();
  for (int sweep = 0; sweep < max_sweeps; ++sweep) {
    if (separate(inverse_mass, next) <= settled_fraction * params_.thickness) break;
  }
  if (friction > 0.0) {
    apply_friction(current, inverse_mass, friction, next);
    for (int sweep = 0; sweep < max_sweeps; ++sweep) {
      if (separate(inverse_mass, next) <= settled_fraction * params_.thickness) break;
    }
  }
  for (const Pair& pair : pairs_) {
    if (!(pair.lambda > 0.0)) continue;
    ++pair_count_;
    for (int k = 0; k < 4; ++k) {
      if (pair.beta[k] != 0.0) in_contact_[pair.vertex[k]] = 1;
    }
  }
  for (const char flag : in_contact_)
    contact_count_ += flag;
  response_ms_ = milliseconds_since(response_start);
}

void SelfCollision::project_again(const Eigen::VectorXd& inverse_mass, Eigen::MatrixXd& next) {
  const auto start = Clock::now();
  for (int sweep = 0; sweep < max_sweeps; ++sweep) {
    if (separate(inverse_mass, next) <= settled_fraction * params_.thickness) break;
  }
  response_ms_ += milliseconds_since(start);
}

}  // namespace wobble

#include "sim/contact/self_collision.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>

#include "sim/input_error.h"
#include "sim/value_limits.h"

namespace wobble {

namespace {

using Clock = std::chrono::steady_clock;

double milliseconds_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The point of triangle abc closest to p, as barycentric coordinates (α_a, α_b, α_c), by the
// region of the triangle's plane p projects into (the three corners, the three edges, the
// inside).
Eigen::Vector3d closest_barycentric(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
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
  if (!(sum > 0.0)) return {1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};  // a degenerate triangle
  return {va / sum, vb / sum, vc / sum};
}

Eigen::Vector3d row(const Eigen::MatrixXd& m, int i) {
  return Eigen::Vector3d(m(i, 0), m(i, 1), m(i, 2));
}

// Cell coordinates to a slot of a table of `slots` entries (a power of two).
std::uint32_t cell_slot(std::int64_t x, std::int64_t y, std::int64_t z, std::uint32_t slots) {
  const std::uint64_t h = static_cast<std::uint64_t>(x) * 73856093u ^
                          static_cast<std::uint64_t>(y) * 19349663u ^
                          static_cast<std::uint64_t>(z) * 83492791u;
  return static_cast<std::uint32_t>(h ^ (h >> 29)) & (slots - 1);
}

// A box covering more cells than this goes on a list every vertex checks instead (a triangle
// that moved far in one step: a dragged pin's).
constexpr std::int64_t max_cells_per_box = 512;

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
  double edge_sum = 0.0;
  for (Eigen::Index t = 0; t < triangles_.rows(); ++t) {
    for (int c = 0; c < 3; ++c) {
      on_surface[triangles_(t, c)] = 1;
      edge_sum += (row(rest_, triangles_(t, c)) - row(rest_, triangles_(t, (c + 1) % 3))).norm();
    }
  }
  for (Eigen::Index i = 0; i < rest.V.rows(); ++i) {
    if (on_surface[i]) surface_vertices_.push_back(static_cast<int>(i));
  }
  // About one triangle's size: each swept box covers a few cells, each cell holds a few boxes.
  const double mean_edge = triangles_.rows() > 0 ? edge_sum / (3.0 * triangles_.rows()) : 1.0;
  cell_ = mean_edge > 0.0 ? mean_edge : 1.0;
  in_contact_.assign(rest.V.rows(), 0);
  seen_.assign(triangles_.rows(), -1);
}

void SelfCollision::clear() {
  std::fill(in_contact_.begin(), in_contact_.end(), 0);
  contact_count_ = 0;
  pair_count_ = 0;
}

void SelfCollision::build_grid(const Eigen::MatrixXd& current, const Eigen::MatrixXd& next) {
  const Eigen::Index triangles = triangles_.rows();
  const double grow = params_.thickness;
  boxes_.resize(triangles);
  std::uint32_t slots = 1;
  while (slots < 2 * static_cast<std::uint64_t>(triangles) + 1)
    slots *= 2;
  cell_start_.assign(slots + 1, 0);
  large_.clear();
  const double inverse_cell = 1.0 / cell_;
  const auto cell_range = [&](const Eigen::AlignedBox3d& box, Eigen::Array3i& low,
                              Eigen::Array3i& high) {
    const Eigen::Array3d lo = (box.min().array() * inverse_cell).floor();
    const Eigen::Array3d hi = (box.max().array() * inverse_cell).floor();
    if (((hi - lo + 1.0).prod()) > static_cast<double>(max_cells_per_box)) return false;
    low = lo.cast<int>();
    high = hi.cast<int>();
    return true;
  };
  // Two passes of a counting sort: how many triangles each slot gets, then the triangles.
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<int> fill;
    if (pass == 1) {
      for (std::uint32_t s = 0; s < slots; ++s)
        cell_start_[s + 1] += cell_start_[s];
      cell_triangles_.resize(cell_start_[slots]);
      fill.assign(cell_start_.begin(), cell_start_.end() - 1);
    }
    for (Eigen::Index t = 0; t < triangles; ++t) {
      if (pass == 0) {
        Eigen::AlignedBox3d box;
        for (int c = 0; c < 3; ++c) {
          box.extend(row(current, triangles_(t, c)));
          box.extend(row(next, triangles_(t, c)));
        }
        box.min().array() -= grow;
        box.max().array() += grow;
        boxes_[t] = box;
      }
      Eigen::Array3i low, high;
      if (!cell_range(boxes_[t], low, high)) {
        if (pass == 0) large_.push_back(static_cast<int>(t));
        continue;
      }
      for (int x = low.x(); x <= high.x(); ++x) {
        for (int y = low.y(); y <= high.y(); ++y) {
          for (int z = low.z(); z <= high.z(); ++z) {
            const std::uint32_t slot = cell_slot(x, y, z, slots);
            if (pass == 0) {
              ++cell_start_[slot + 1];
            } else {
              cell_triangles_[fill[slot]++] = static_cast<int>(t);
            }
          }
        }
      }
    }
  }
}

void SelfCollision::detect(const Eigen::MatrixXd& current, const Eigen::MatrixXd& next) {
  build_grid(current, next);
  pairs_.clear();
  std::fill(seen_.begin(), seen_.end(), -1);
  const double h = params_.thickness;
  const std::uint32_t slots = static_cast<std::uint32_t>(cell_start_.size() - 1);
  const double inverse_cell = 1.0 / cell_;

  const auto consider = [&](int v, int t, const Eigen::AlignedBox3d& vertex_box) {
    if (seen_[t] == v) return;
    seen_[t] = v;
    const int a = triangles_(t, 0), b = triangles_(t, 1), c = triangles_(t, 2);
    if (v == a || v == b || v == c) return;
    if (!vertex_box.intersects(boxes_[t])) return;
    // Where the pair starts, and how much closer it can come: the distance from the vertex to
    // the triangle changes by at most the largest motion of a corner relative to the vertex.
    const Eigen::Vector3d v0 = row(current, v);
    const Eigen::Vector3d a0 = row(current, a), b0 = row(current, b), c0 = row(current, c);
    const Eigen::Vector3d alpha = closest_barycentric(v0, a0, b0, c0);
    const Eigen::Vector3d q0 = alpha(0) * a0 + alpha(1) * b0 + alpha(2) * c0;
    const double d0 = (v0 - q0).norm();
    const Eigen::Vector3d moved = row(next, v) - v0;
    double closing = 0.0;
    for (const int corner : {a, b, c}) {
      closing = std::max(closing, (row(next, corner) - row(current, corner) - moved).norm());
    }
    if (d0 - closing >= h) return;
    // Pairs this close in the rest shape (a fine mesh's near neighbours) are left alone.
    const Eigen::Vector3d rv = row(rest_, v);
    const Eigen::Vector3d ra = row(rest_, a), rb = row(rest_, b), rc = row(rest_, c);
    const Eigen::Vector3d rest_alpha = closest_barycentric(rv, ra, rb, rc);
    if ((rv - (rest_alpha(0) * ra + rest_alpha(1) * rb + rest_alpha(2) * rc)).norm() < h) return;
    Eigen::Vector3d normal;
    if (d0 > 1e-9 * h) {
      normal = (v0 - q0) / d0;
    } else {
      // On the triangle at the start (nothing kept it off): its face normal, on the side the
      // vertex ends on.
      normal = (b0 - a0).cross(c0 - a0);
      if (normal.squaredNorm() == 0.0) return;
      normal.normalize();
      const Eigen::Vector3d q =
          alpha(0) * row(next, a) + alpha(1) * row(next, b) + alpha(2) * row(next, c);
      if ((row(next, v) - q).dot(normal) < 0.0) normal = -normal;
    }
    pairs_.push_back(Pair{v, t, alpha, normal, 0.0});
  };

  for (const int v : surface_vertices_) {
    Eigen::AlignedBox3d box(row(current, v));
    box.extend(row(next, v));
    const Eigen::Array3d lo = (box.min().array() * inverse_cell).floor();
    const Eigen::Array3d hi = (box.max().array() * inverse_cell).floor();
    if ((hi - lo + 1.0).prod() > static_cast<double>(max_cells_per_box)) {
      // A vertex that moved far: every triangle.
      for (Eigen::Index t = 0; t < triangles_.rows(); ++t)
        consider(v, static_cast<int>(t), box);
      continue;
    }
    for (int x = static_cast<int>(lo.x()); x <= hi.x(); ++x) {
      for (int y = static_cast<int>(lo.y()); y <= hi.y(); ++y) {
        for (int z = static_cast<int>(lo.z()); z <= hi.z(); ++z) {
          const std::uint32_t slot = cell_slot(x, y, z, slots);
          for (int s = cell_start_[slot]; s < cell_start_[slot + 1]; ++s)
            consider(v, cell_triangles_[s], box);
        }
      }
    }
    for (const int t : large_)
      consider(v, t, box);
  }
}

void SelfCollision::project(const Eigen::MatrixXd& current, const Eigen::VectorXd& inverse_mass,
                            double friction, Eigen::MatrixXd& next) {
  std::fill(in_contact_.begin(), in_contact_.end(), 0);
  contact_count_ = 0;
  pair_count_ = 0;
  const auto detection_start = Clock::now();
  detect(current, next);
  detection_ms_ = milliseconds_since(detection_start);

  const auto response_start = Clock::now();
  const double h = params_.thickness;
  // The gap of pair p along its normal, and the weight of a push on it.
  const auto gap = [&](const Pair& p) {
    const Eigen::Vector3d q = p.alpha(0) * row(next, triangles_(p.triangle, 0)) +
                              p.alpha(1) * row(next, triangles_(p.triangle, 1)) +
                              p.alpha(2) * row(next, triangles_(p.triangle, 2));
    return (row(next, p.vertex) - q).dot(p.normal);
  };
  const auto weight = [&](const Pair& p) {
    double w = inverse_mass(p.vertex);
    for (int c = 0; c < 3; ++c)
      w += p.alpha(c) * p.alpha(c) * inverse_mass(triangles_(p.triangle, c));
    return w;
  };
  // Moves the pair's vertex by w_v·λ·d and each corner by −αᵢwᵢ·λ·d.
  const auto push = [&](const Pair& p, double lambda, const Eigen::Vector3d& direction) {
    next.row(p.vertex) += (inverse_mass(p.vertex) * lambda) * direction.transpose();
    for (int c = 0; c < 3; ++c) {
      const int corner = triangles_(p.triangle, c);
      next.row(corner) -= (p.alpha(c) * inverse_mass(corner) * lambda) * direction.transpose();
    }
  };
  const auto separate = [&]() {
    double worst = 0.0;
    for (Pair& p : pairs_) {
      const double violation = h - gap(p);
      if (!(violation > 0.0)) continue;
      const double w = weight(p);
      if (!(w > 0.0)) continue;  // four pinned vertices
      const double lambda = violation / w;
      push(p, lambda, p.normal);
      p.lambda += lambda;
      worst = std::max(worst, violation);
    }
    return worst;
  };
  // Gauss-Seidel sweeps until every pair keeps the thickness to a thousandth.
  constexpr int max_sweeps = 16;
  for (int sweep = 0; sweep < max_sweeps; ++sweep) {
    if (separate() <= 1e-3 * h) break;
  }
  if (friction > 0.0) {
    for (const Pair& p : pairs_) {
      if (!(p.lambda > 0.0)) continue;
      const double w = weight(p);
      // The pair's relative motion over the step, less its normal part.
      Eigen::Vector3d relative = row(next, p.vertex) - row(current, p.vertex);
      for (int c = 0; c < 3; ++c) {
        const int corner = triangles_(p.triangle, c);
        relative -= p.alpha(c) * (row(next, corner) - row(current, corner));
      }
      const Eigen::Vector3d tangential = relative - relative.dot(p.normal) * p.normal;
      const double slide = tangential.norm();
      if (!(slide > 0.0)) continue;
      const double budget = friction * p.lambda * w;  // μ times the depth pushed out
      const double undone = std::min(slide, budget);
      push(p, -undone / w, tangential / slide);
    }
    separate();
  }
  for (const Pair& p : pairs_) {
    if (!(p.lambda > 0.0)) continue;
    ++pair_count_;
    in_contact_[p.vertex] = 1;
    for (int c = 0; c < 3; ++c)
      in_contact_[triangles_(p.triangle, c)] = 1;
  }
  for (const char flag : in_contact_)
    contact_count_ += flag;
  response_ms_ = milliseconds_since(response_start);
}

}  // namespace wobble

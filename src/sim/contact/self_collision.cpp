#include "sim/contact/self_collision.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
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
// The motion detection allows beyond the solve's, as a fraction of the thickness, and how often
// the pairs are found again when the response pushed a vertex farther.
constexpr double margin_fraction = 0.25;
constexpr int max_rounds = 3;
// The pairs of a slow step are kept while no vertex strays farther than half this fraction of
// the thickness from where they were found.
constexpr double skin_fraction = 0.5;
// How much of the thickness a pair that starts too close may open up by in one step.
constexpr double recovery_fraction = 0.1;
// Pairs closer than this many thicknesses in the rest shape are the mesh's own neighbourhood.
constexpr double rest_skip_factor = 2.0;

// Whether segment pq passes through triangle abc: p and q strictly on opposite sides of its
// plane, and the line pq inside or on all three of its edges (signed volumes).
bool segment_crosses_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                              const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                              const Eigen::Vector3d& c) {
  const auto volume = [](const Eigen::Vector3d& w, const Eigen::Vector3d& x,
                         const Eigen::Vector3d& y,
                         const Eigen::Vector3d& z) { return (x - w).dot((y - w).cross(z - w)); };
  const double side_p = volume(a, b, c, p), side_q = volume(a, b, c, q);
  if (!((side_p > 0.0 && side_q < 0.0) || (side_p < 0.0 && side_q > 0.0))) return false;
  const double u = volume(p, q, a, b), v = volume(p, q, b, c), w = volume(p, q, c, a);
  return (u >= 0.0 && v >= 0.0 && w >= 0.0) || (u <= 0.0 && v <= 0.0 && w <= 0.0);
}

// Whether `id` is among list[start[owner]] to list[start[owner + 1] − 1] (sorted).
bool listed(const std::vector<int>& start, const std::vector<int>& list, int owner, int id) {
  return std::binary_search(list.begin() + start[owner], list.begin() + start[owner + 1], id);
}

// Lists of (owner, id) pairs as compressed rows: start (#owners + 1) and ids.
void compress(std::vector<std::pair<int, int>>& pairs, int owners, std::vector<int>& start,
              std::vector<int>& ids) {
  std::sort(pairs.begin(), pairs.end());
  start.assign(owners + 1, 0);
  ids.resize(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    ++start[pairs[k].first + 1];
    ids[k] = pairs[k].second;
  }
  for (int o = 0; o < owners; ++o)
    start[o + 1] += start[o];
}

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
  const double cell = mean_edge > 0.0 ? 1.5 * mean_edge : 1.0;
  triangle_grid_ = SpatialGrid(cell);
  edge_grid_ = SpatialGrid(cell);
  in_contact_.assign(rest.V.rows(), 0);
  seen_triangle_.assign(triangles_.rows(), -1);
  seen_edge_.assign(edges_.rows(), -1);
  triangle_checked_.assign(triangles_.rows(), -1);
  edge_checked_.assign(edges_.rows(), -1);
  std::vector<std::pair<int, int>> incident;
  for (Eigen::Index e = 0; e < edges_.rows(); ++e) {
    incident.emplace_back(edges_(e, 0), static_cast<int>(e));
    incident.emplace_back(edges_(e, 1), static_cast<int>(e));
  }
  compress(incident, static_cast<int>(rest.V.rows()), vertex_edges_start_, vertex_edges_);
  incident.clear();
  for (Eigen::Index t = 0; t < triangles_.rows(); ++t) {
    for (int c = 0; c < 3; ++c)
      incident.emplace_back(triangles_(t, c), static_cast<int>(t));
  }
  compress(incident, static_cast<int>(rest.V.rows()), vertex_triangles_start_, vertex_triangles_);
  find_rest_neighbours();
}

void SelfCollision::set_thickness(double thickness) {
  if (thickness == params_.thickness) return;
  params_.thickness = thickness;
  listed_ = false;
  find_rest_neighbours();
}

void SelfCollision::find_rest_neighbours() {
  const double reach = rest_skip_factor * params_.thickness;
  const Eigen::MatrixXd& V = rest_;
  // Rest boxes grown by half the reach: pairs within it have overlapping boxes.
  const auto grown = [&](std::initializer_list<int> vertices) {
    Eigen::AlignedBox3d box;
    for (const int i : vertices)
      box.extend(row(V, i));
    box.min().array() -= 0.5 * reach;
    box.max().array() += 0.5 * reach;
    return box;
  };
  std::vector<std::pair<int, int>> found;
  triangle_boxes_.resize(triangles_.rows());
  for (Eigen::Index t = 0; t < triangles_.rows(); ++t)
    triangle_boxes_[t] = grown({triangles_(t, 0), triangles_(t, 1), triangles_(t, 2)});
  triangle_grid_.build(triangle_boxes_);
  for (const int v : surface_vertices_) {
    next_stamp();
    const Eigen::AlignedBox3d box = grown({v});
    triangle_grid_.for_each_candidate(box, [&](int t) {
      if (seen_triangle_[t] == stamp_) return;
      seen_triangle_[t] = stamp_;
      const int a = triangles_(t, 0), b = triangles_(t, 1), c = triangles_(t, 2);
      if (v == a || v == b || v == c || !box.intersects(triangle_boxes_[t])) return;
      const Eigen::Vector3d alpha = closest_on_triangle(row(V, v), row(V, a), row(V, b), row(V, c));
      const Eigen::Vector3d q = alpha(0) * row(V, a) + alpha(1) * row(V, b) + alpha(2) * row(V, c);
      if ((row(V, v) - q).norm() < reach) found.emplace_back(v, t);
    });
  }
  compress(found, static_cast<int>(V.rows()), rest_triangles_start_, rest_triangles_);
  found.clear();
  edge_boxes_.resize(edges_.rows());
  for (Eigen::Index e = 0; e < edges_.rows(); ++e)
    edge_boxes_[e] = grown({edges_(e, 0), edges_(e, 1)});
  edge_grid_.build(edge_boxes_);
  edge_grid_.for_each_overlapping_pair([&](int e, int f) {
    const int p0 = edges_(e, 0), p1 = edges_(e, 1), q0 = edges_(f, 0), q1 = edges_(f, 1);
    if (q0 == p0 || q0 == p1 || q1 == p0 || q1 == p1) return;
    const Eigen::Vector2d su = closest_on_segments(row(V, p0), row(V, p1), row(V, q0), row(V, q1));
    const Eigen::Vector3d gap = (1.0 - su(0)) * row(V, p0) + su(0) * row(V, p1) -
                                (1.0 - su(1)) * row(V, q0) - su(1) * row(V, q1);
    if (gap.norm() < reach) found.emplace_back(e, f);  // e < f
  });
  compress(found, static_cast<int>(edges_.rows()), rest_edges_start_, rest_edges_);
}

void SelfCollision::clear() {
  listed_ = false;
  pairs_.clear();
  listed_pairs_.clear();
  std::fill(in_contact_.begin(), in_contact_.end(), 0);
  contact_count_ = 0;
  pair_count_ = 0;
}

void SelfCollision::sweep_boxes(const Eigen::MatrixXd& current, const Eigen::MatrixXd& next,
                                double margin) {
  // Two features closer than the thickness have boxes closer than that along every axis: each
  // box grows by half of it, and by the margin its vertices may still be pushed.
  const double grow = 0.5 * params_.thickness + margin;
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
                                  const Eigen::MatrixXd& next, double margin) {
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
  if (distance - closing_first - closing_second >= h + 2.0 * margin) return;
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
  // A pair that starts closer than the thickness (the last step's sweeps left it short, or two
  // layers were made that close) opens by at most a tenth of it a step: pushed out at once it
  // would leave with the whole shortfall as speed, and a pile kept on bouncing.
  pair.target = std::min(h, std::max(distance, 0.0) + recovery_fraction * h);
  pairs_.push_back(pair);
}

void SelfCollision::find_vertex_triangle_pairs(const Eigen::MatrixXd& current,
                                               const Eigen::MatrixXd& next, double margin) {
  for (const int v : surface_vertices_) {
    next_stamp();
    Eigen::AlignedBox3d box(row(current, v));
    box.extend(row(next, v));
    box.min().array() -= 0.5 * params_.thickness + margin;
    box.max().array() += 0.5 * params_.thickness + margin;
    const Eigen::Vector3d v0 = row(current, v);
    triangle_grid_.for_each_candidate(box, [&](int t) {
      if (seen_triangle_[t] == stamp_) return;
      seen_triangle_[t] = stamp_;
      const int a = triangles_(t, 0), b = triangles_(t, 1), c = triangles_(t, 2);
      if (v == a || v == b || v == c || !box.intersects(triangle_boxes_[t])) return;
      if (listed(rest_triangles_start_, rest_triangles_, v, t)) return;
      const Eigen::Vector3d alpha =
          closest_on_triangle(v0, row(current, a), row(current, b), row(current, c));
      keep_if_close(Pair{{v, a, b, c}, {1.0, -alpha(0), -alpha(1), -alpha(2)}, {}, 0.0, 0.0, true},
                    1, current, next, margin);
    });
  }
}

void SelfCollision::find_edge_edge_pairs(const Eigen::MatrixXd& current,
                                         const Eigen::MatrixXd& next, double margin) {
  edge_grid_.for_each_overlapping_pair([&](int e, int f) {
    const int p0 = edges_(e, 0), p1 = edges_(e, 1), q0 = edges_(f, 0), q1 = edges_(f, 1);
    if (q0 == p0 || q0 == p1 || q1 == p0 || q1 == p1) return;
    if (listed(rest_edges_start_, rest_edges_, e, f)) return;
    const Eigen::Vector2d su =
        closest_on_segments(row(current, p0), row(current, p1), row(current, q0), row(current, q1));
    keep_if_close(
        Pair{{p0, p1, q0, q1}, {1.0 - su(0), su(0), -(1.0 - su(1)), -su(1)}, {}, 0.0, 0.0, false},
        2, current, next, margin);
  });
}

namespace {

// Moves the pair's vertices so that Σβₖxₖ moves by `amount` (m) along `direction`, each vertex
// by wₖβₖλ; returns λ. No vertex moves farther than `amount`: when the only vertex free to move
// has a small weight βₖ (a triangle's corner far from the contact, the others pinned), the
// full correction would throw it amount/βₖ away; the pair then gets only part of it.
template <typename PairT>
double push(const PairT& pair, double amount, const Eigen::Vector3d& direction,
            const Eigen::VectorXd& inverse_mass, Eigen::MatrixXd& next) {
  double weight = 0.0, largest = 0.0;
  for (int k = 0; k < 4; ++k) {
    const double w = inverse_mass(pair.vertex[k]);
    weight += pair.beta[k] * pair.beta[k] * w;
    largest = std::max(largest, w * std::abs(pair.beta[k]));
  }
  if (!(weight > 0.0)) return 0.0;  // nothing can move
  const double lambda = std::min(amount / weight, amount / largest);
  for (int k = 0; k < 4; ++k) {
    const int i = pair.vertex[k];
    next.row(i) += (inverse_mass(i) * pair.beta[k] * lambda) * direction.transpose();
  }
  return lambda;
}

}  // namespace

double SelfCollision::separate(const Eigen::VectorXd& inverse_mass, Eigen::MatrixXd& next) {
  double worst = 0.0;
  for (Pair& pair : pairs_) {
    double gap = 0.0;
    for (int k = 0; k < 4; ++k) {
      const int i = pair.vertex[k];
      gap += pair.beta[k] * (next(i, 0) * pair.normal(0) + next(i, 1) * pair.normal(1) +
                             next(i, 2) * pair.normal(2));
    }
    const double violation = pair.target - gap;
    if (!(violation > 0.0)) continue;
    pair.depth += push(pair, violation, pair.normal, inverse_mass, next) > 0.0 ? violation : 0.0;
    worst = std::max(worst, violation);
  }
  return worst;
}

void SelfCollision::apply_friction(const Eigen::MatrixXd& current,
                                   const Eigen::VectorXd& inverse_mass, double friction,
                                   Eigen::MatrixXd& next) {
  for (const Pair& pair : pairs_) {
    // Only a vertex over a triangle's face (its closest point inside): there the normal is the
    // face's, and what is tangential slides along the layer. Friction on edge-edge pairs too
    // kept a 32×32 pile on the ground bouncing (0.1–0.8 J six seconds in), and on a vertex
    // beside a triangle (an oblique normal, so motion across the layer counted as sliding) a
    // settled pile crept and came back to life (10⁻⁷ J to 0.03 J from 4 s to 8 s).
    if (!(pair.depth > 0.0) || !pair.vertex_triangle) continue;
    if (!(pair.beta[1] < 0.0 && pair.beta[2] < 0.0 && pair.beta[3] < 0.0)) continue;
    // The pair's relative motion over the step, less its normal part.
    Eigen::Vector3d relative = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k)
      relative += pair.beta[k] * (row(next, pair.vertex[k]) - row(current, pair.vertex[k]));
    const Eigen::Vector3d tangential = relative - relative.dot(pair.normal) * pair.normal;
    const double slide = tangential.norm();
    if (!(slide > 0.0)) continue;
    // Coulomb: the slide shrinks by μ times the depth the pair was pushed out, at most to rest.
    push(pair, std::min(slide, friction * pair.depth), -tangential / slide, inverse_mass, next);
  }
}

bool SelfCollision::near_reference(const Eigen::MatrixXd& positions, double reach) const {
  const double reach2 = reach * reach;
  for (const int v : surface_vertices_) {
    double distance2 = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double d = positions(v, c) - reference_(v, c);
      distance2 += d * d;
    }
    if (!(distance2 <= reach2)) return false;
  }
  return true;
}

void SelfCollision::refresh_pairs(const Eigen::MatrixXd& current) {
  const double h = params_.thickness;
  pairs_.resize(listed_pairs_.size());
  std::size_t kept = 0;
  for (Pair pair : listed_pairs_) {
    const Eigen::Vector3d p0 = row(current, pair.vertex[0]), p1 = row(current, pair.vertex[1]);
    const Eigen::Vector3d p2 = row(current, pair.vertex[2]), p3 = row(current, pair.vertex[3]);
    // The closest points of the two features where the step starts.
    if (pair.vertex_triangle) {
      const Eigen::Vector3d alpha = closest_on_triangle(p0, p1, p2, p3);
      pair.beta[1] = -alpha(0);
      pair.beta[2] = -alpha(1);
      pair.beta[3] = -alpha(2);
    } else {
      const Eigen::Vector2d su = closest_on_segments(p0, p1, p2, p3);
      pair.beta[0] = 1.0 - su(0);
      pair.beta[1] = su(0);
      pair.beta[2] = -(1.0 - su(1));
      pair.beta[3] = -su(1);
    }
    const Eigen::Vector3d start =
        pair.beta[0] * p0 + pair.beta[1] * p1 + pair.beta[2] * p2 + pair.beta[3] * p3;
    const double distance = start.norm();
    if (distance > 1e-9 * h) pair.normal = start / distance;  // else the last step's normal
    pair.target = std::min(h, distance + recovery_fraction * h);
    pair.depth = 0.0;
    pairs_[kept++] = pair;
  }
  pairs_.resize(kept);
}

void SelfCollision::respond(const Eigen::MatrixXd& current, const Eigen::VectorXd& inverse_mass,
                            double friction, Eigen::MatrixXd& next) {
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
    if (!(pair.depth > 0.0)) continue;
    ++pair_count_;
    for (int k = 0; k < 4; ++k) {
      if (pair.beta[k] != 0.0) in_contact_[pair.vertex[k]] = 1;
    }
  }
}

void SelfCollision::detect(const Eigen::MatrixXd& current, const Eigen::MatrixXd& end,
                           double allowance) {
  sweep_boxes(current, end, allowance);
  triangle_grid_.build(triangle_boxes_);
  edge_grid_.build(edge_boxes_);
  pairs_.clear();
  find_vertex_triangle_pairs(current, end, allowance);
  find_edge_edge_pairs(current, end, allowance);
}

bool SelfCollision::near_segments(const Eigen::MatrixXd& current, const Eigen::MatrixXd& end,
                                  const Eigen::MatrixXd& positions, double reach) const {
  for (const int v : surface_vertices_) {
    const Eigen::Vector3d from = row(current, v), along = row(end, v) - from;
    const Eigen::Vector3d p = row(positions, v);
    const double length2 = along.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp((p - from).dot(along) / length2, 0.0, 1.0) : 0.0;
    if (!((p - from - t * along).norm() <= reach)) return false;
  }
  return true;
}

void SelfCollision::project(const Eigen::MatrixXd& current, const Eigen::VectorXd& inverse_mass,
                            double friction, Eigen::MatrixXd& next) {
  std::fill(in_contact_.begin(), in_contact_.end(), 0);
  contact_count_ = pair_count_ = undone_ = 0;
  detection_ms_ = response_ms_ = 0.0;
  const double h = params_.thickness;
  const double skin = skin_fraction * h;
  const double margin = margin_fraction * h;
  solved_ = next;

  // At rest (a settled pile), the pairs found around where the surface rests serve step after
  // step: every pair left out was at least the thickness plus the skin apart there, so it
  // cannot come within the thickness while no vertex strays half the skin from there.
  if (listed_ && near_reference(current, 0.5 * skin)) {
    const auto detection_start = Clock::now();
    refresh_pairs(current);
    detection_ms_ += milliseconds_since(detection_start);
    const auto response_start = Clock::now();
    respond(current, inverse_mass, friction, next);
    response_ms_ += milliseconds_since(response_start);
    if (near_reference(next, 0.5 * skin)) return;
    next = solved_;
    std::fill(in_contact_.begin(), in_contact_.end(), 0);
    pair_count_ = 0;
  }
  listed_ = false;

  // Otherwise the pairs the step's motion can bring within the thickness, with a margin for the
  // response's pushes; when a push takes a vertex farther from its path than the margin, the
  // pairs are found again along the pushed path.
  Eigen::MatrixXd* end = &solved_;
  for (int round = 0; round < max_rounds; ++round) {
    const auto detection_start = Clock::now();
    if (round > 0) {
      pushed_ = next;
      next = solved_;
      end = &pushed_;
    }
    detect(current, *end, margin);
    detection_ms_ += milliseconds_since(detection_start);
    const auto response_start = Clock::now();
    respond(current, inverse_mass, friction, next);
    response_ms_ += milliseconds_since(response_start);
    if (near_segments(current, *end, next, margin)) break;
  }

  // A step that hardly moved: the pairs around where it ends, for the next steps.
  if ((next - current).rowwise().norm().maxCoeff() <= 0.25 * skin) {
    const auto detection_start = Clock::now();
    std::vector<Pair> pushed_pairs;
    pushed_pairs.swap(pairs_);
    detect(next, next, 0.5 * skin);
    reference_ = next;
    listed_ = true;
    listed_pairs_.swap(pairs_);
    pairs_.swap(pushed_pairs);
    detection_ms_ += milliseconds_since(detection_start);
  }
}

void SelfCollision::finish(const Eigen::MatrixXd& current, const Eigen::VectorXd& inverse_mass,
                           Eigen::MatrixXd& next) {
  undo_crossings(current, inverse_mass, next);
  contact_count_ = 0;
  for (const char flag : in_contact_)
    contact_count_ += flag;
}

void SelfCollision::next_stamp() {
  if (stamp_ == std::numeric_limits<int>::max()) {
    // Start again, before a stamp could repeat.
    for (std::vector<int>* seen :
         {&seen_triangle_, &seen_edge_, &triangle_checked_, &edge_checked_})
      std::fill(seen->begin(), seen->end(), -1);
    stamp_ = 0;
  }
  ++stamp_;
}

bool SelfCollision::crosses(int edge, int triangle, const Eigen::MatrixXd& current,
                            const Eigen::MatrixXd& next) const {
  const int p = edges_(edge, 0), q = edges_(edge, 1);
  const int a = triangles_(triangle, 0), b = triangles_(triangle, 1), c = triangles_(triangle, 2);
  if (p == a || p == b || p == c || q == a || q == b || q == c) return false;
  if (!edge_boxes_[edge].intersects(triangle_boxes_[triangle])) return false;
  if (!segment_crosses_triangle(row(next, p), row(next, q), row(next, a), row(next, b),
                                row(next, c))) {
    return false;
  }
  // A crossing the step started with (a tangle from before) is not this step's doing.
  return !segment_crosses_triangle(row(current, p), row(current, q), row(current, a),
                                   row(current, b), row(current, c));
}

void SelfCollision::undo_crossings(const Eigen::MatrixXd& current,
                                   const Eigen::VectorXd& inverse_mass, Eigen::MatrixXd& next) {
  const auto start = Clock::now();
  frozen_.assign(next.rows(), 0);
  std::vector<int>& changed = changed_;
  changed.clear();
  for (int round = 0;; ++round) {
    // Where the triangles and edges end, as boxes, in their grids.
    for (Eigen::Index t = 0; t < triangles_.rows(); ++t) {
      Eigen::AlignedBox3d box(row(next, triangles_(t, 0)));
      box.extend(row(next, triangles_(t, 1)));
      box.extend(row(next, triangles_(t, 2)));
      triangle_boxes_[t] = box;
    }
    for (Eigen::Index e = 0; e < edges_.rows(); ++e) {
      Eigen::AlignedBox3d box(row(next, edges_(e, 0)));
      box.extend(row(next, edges_(e, 1)));
      edge_boxes_[e] = box;
    }
    triangle_grid_.build(triangle_boxes_);
    if (round > 0) edge_grid_.build(edge_boxes_);
    crossed_.clear();
    // A crossing a pinned vertex makes is left alone: the pin follows its target, and putting
    // the rest back would only hold the cloth still in its way.
    const auto add_crossing = [&](int e, int t) {
      const int vertices[5] = {edges_(e, 0), edges_(e, 1), triangles_(t, 0), triangles_(t, 1),
                               triangles_(t, 2)};
      for (const int v : vertices) {
        if (!(inverse_mass(v) > 0.0)) return;
      }
      crossed_.insert(crossed_.end(), vertices, vertices + 5);
    };
    const auto check_edge = [&](int e) {
      next_stamp();
      triangle_grid_.for_each_candidate(edge_boxes_[e], [&](int t) {
        if (seen_triangle_[t] == stamp_) return;
        seen_triangle_[t] = stamp_;
        if (crosses(e, t, current, next)) add_crossing(e, t);
      });
    };
    if (round == 0) {
      // Every edge against every triangle near it.
      for (Eigen::Index e = 0; e < edges_.rows(); ++e)
        check_edge(static_cast<int>(e));
    } else {
      // Only what touches a vertex just put back can cross anything new.
      next_stamp();
      const int round_stamp = stamp_;
      for (const int v : changed) {
        for (int s = vertex_edges_start_[v]; s < vertex_edges_start_[v + 1]; ++s) {
          const int e = vertex_edges_[s];
          if (edge_checked_[e] == round_stamp) continue;
          edge_checked_[e] = round_stamp;
          check_edge(e);
        }
        for (int s = vertex_triangles_start_[v]; s < vertex_triangles_start_[v + 1]; ++s) {
          const int t = vertex_triangles_[s];
          if (triangle_checked_[t] == round_stamp) continue;
          triangle_checked_[t] = round_stamp;
          next_stamp();
          edge_grid_.for_each_candidate(triangle_boxes_[t], [&](int e) {
            if (seen_edge_[e] == stamp_) return;
            seen_edge_[e] = stamp_;
            if (crosses(e, t, current, next)) add_crossing(e, t);
          });
        }
      }
    }
    // The crossing vertices and their neighbours go back to where they started (a pinned
    // neighbour stays with its target).
    changed.clear();
    const auto put_back = [&](int v) {
      if (frozen_[v] || !(inverse_mass(v) > 0.0)) return;
      frozen_[v] = 1;
      next.row(v) = current.row(v);
      in_contact_[v] = 1;
      changed.push_back(v);
    };
    for (const int v : crossed_) {
      put_back(v);
      for (int s = vertex_edges_start_[v]; s < vertex_edges_start_[v + 1]; ++s) {
        const int e = vertex_edges_[s];
        put_back(edges_(e, 0) == v ? edges_(e, 1) : edges_(e, 0));
      }
    }
    undone_ += static_cast<int>(changed.size());
    // Every vertex that could move has gone back: the step ends where it started, but for pins.
    if (changed.empty()) break;
  }
  response_ms_ += milliseconds_since(start);
}

void SelfCollision::project_again(const Eigen::VectorXd& inverse_mass, Eigen::MatrixXd& next) {
  const auto start = Clock::now();
  for (int sweep = 0; sweep < max_sweeps; ++sweep) {
    if (separate(inverse_mass, next) <= settled_fraction * params_.thickness) break;
  }
  response_ms_ += milliseconds_since(start);
}

}  // namespace wobble

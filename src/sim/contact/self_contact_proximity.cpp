#include "sim/contact/self_contact_proximity.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "sim/contact/closest_points.h"
#include "sim/contact/vertex_row.h"

namespace wobble {

namespace {

// The queries are cut into this many chunks a kind, whatever the thread count, so that the
// pairs come out in the same order on any machine.
constexpr int chunks_per_kind = 64;

constexpr double infinity = std::numeric_limits<double>::infinity();

struct Range {
  int first, last;
};
// Piece `piece` of chunks_per_kind of [0, count).
Range chunk_range(int count, int piece) {
  const long long n = count;
  return {static_cast<int>(n * piece / chunks_per_kind),
          static_cast<int>(n * (piece + 1) / chunks_per_kind)};
}

Eigen::AlignedBox3d grown(Eigen::AlignedBox3d box, double by) {
  box.min().array() -= by;
  box.max().array() += by;
  return box;
}

// How far apart two boxes are along each axis (0 where they overlap on it).
inline Eigen::Array3d box_gap(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b) {
  return (a.min().array() - b.max().array()).max(b.min().array() - a.max().array()).max(0.0);
}

// Whether a triangle other than `t` holds both a and b and not v.
bool has_triangle_across(const SelfCollisionSurface& surface, int a, int b, int t, int v) {
  const CompressedRows& rows = surface.vertex_triangles;
  int i = rows.begin(a), j = rows.begin(b);
  while (i < rows.end(a) && j < rows.end(b)) {
    const int s = rows.ids[i], u = rows.ids[j];
    if (s < u) {
      ++i;
    } else if (u < s) {
      ++j;
    } else {
      if (s != t && surface.triangles(s, 0) != v && surface.triangles(s, 1) != v &&
          surface.triangles(s, 2) != v) {
        return true;
      }
      ++i;
      ++j;
    }
  }
  return false;
}

// A normal for two features that touch: the first of these that has a direction.
Eigen::Vector3d touching_normal(const Eigen::Vector3d& across, const Eigen::Vector3d& along) {
  if (across.squaredNorm() > 0.0) return across.normalized();
  if (along.squaredNorm() > 0.0) return along.unitOrthogonal();
  return Eigen::Vector3d::UnitZ();
}

}  // namespace

void SelfContactProximity::find(const SelfCollisionSurface& surface, const RestNeighbours& rest,
                                const Eigen::MatrixXd& x, const Eigen::VectorXd& reach,
                                double contact_distance, std::vector<SelfContactPair>& pairs,
                                Eigen::VectorXd& bounds) {
  surface_ = &surface;
  rest_ = &rest;
  contact_distance_ = contact_distance > 0.0 ? contact_distance : 0.0;
  prepare(x, reach);

  // Cells the size of most boxes: each box covers a few cells, each cell holds a few boxes.
  double cell = std::max(surface.mean_edge, contact_distance_);
  if (!extents_.empty()) {
    const auto quartile = extents_.begin() + static_cast<std::ptrdiff_t>(3 * extents_.size() / 4);
    std::nth_element(extents_.begin(), quartile, extents_.end());
    if (std::isfinite(*quartile) && *quartile > 0.0) cell = *quartile;
  }
  triangle_grid_.build(triangle_grown_, cell);
  edge_grid_.build(edge_grown_, cell);

  chunks_.resize(2 * chunks_per_kind);
  const int vertex_count = static_cast<int>(surface.vertices.size());
  auto task = [&](int index) {
    Chunk& chunk = chunks_[index];
    chunk.pairs.clear();
    chunk.frozen.clear();
    const bool vertices = index < chunks_per_kind;
    const Range range = chunk_range(vertex_count, index % chunks_per_kind);
    for (int k = range.first; k < range.last; ++k) {
      if (vertices) {
        query_vertex(surface.vertices[k], chunk);
      } else {
        query_edges(surface.vertices[k], chunk);
      }
    }
  };
  pool().run(2 * chunks_per_kind, task, &payoff_);

  pairs.clear();
  frozen_boxes_.clear();
  for (const Chunk& chunk : chunks_) {
    pairs.insert(pairs.end(), chunk.pairs.begin(), chunk.pairs.end());
    frozen_boxes_.insert(frozen_boxes_.end(), chunk.frozen.begin(), chunk.frozen.end());
  }
  saturated_ = !frozen_boxes_.empty();
  if (saturated_) freeze_near_saturated_queries(cell);

  bounds.setConstant(x.rows(), infinity);
  for (const int v : surface.vertices)
    bounds(v) = 0.5 * bound_fraction * nearest(v);
}

void SelfContactProximity::prepare(const Eigen::MatrixXd& x, const Eigen::VectorXd& reach) {
  const SelfCollisionSurface& surface = *surface_;
  const int n = static_cast<int>(x.rows());
  // Packed rows: a column-major x would cost three cache lines a vertex in the queries.
  points_.resize(n);
  Eigen::AlignedBox3d whole;
  for (int v = 0; v < n; ++v)
    points_[v] = vertex_row(x, v);
  for (const int v : surface.vertices)
    whole.extend(points_[v]);
  const double largest = whole.isEmpty() ? 0.0 : whole.diagonal().norm();
  reach_.assign(n, 0.0);
  for (const int v : surface.vertices) {
    const double r = v < reach.size() ? reach(v) : 0.0;
    reach_[v] = r > 0.0 ? std::min(r, largest) : 0.0;
  }
  // A pair lowers no bound unless it is closer than the largest seed of its vertices, so the
  // boxes need only grow by the seeds, which follow the mesh's spacing rather than the reach.
  seed_.resize(n);
  const int vertex_count = static_cast<int>(surface.vertices.size());
  auto seed_task = [&](int piece) {
    const Range range = chunk_range(vertex_count, piece);
    for (int k = range.first; k < range.last; ++k)
      seed_vertex(surface.vertices[k]);
  };
  pool().run(chunks_per_kind, seed_task, &seed_payoff_);
  if (nearest_capacity_ < static_cast<std::size_t>(n)) {
    nearest_.reset(new std::atomic<double>[n]);
    nearest_capacity_ = n;
  }
  for (const int v : surface.vertices)
    nearest_[v].store(seed_[v], std::memory_order_relaxed);

  const double half_contact = 0.5 * contact_distance_;
  const auto feature = [&](std::initializer_list<int> vertices, Feature& f, double& seed) {
    f = Feature{Eigen::AlignedBox3d(), 0.0, {-1, -1, -1}};
    seed = half_contact;  // so that the grids also meet every contact pair
    int k = 0;
    for (const int v : vertices) {
      f.box.extend(points_[v]);
      f.reach = std::max(f.reach, reach_[v]);
      seed = std::max(seed, seed_[v]);
      f.vertex[k++] = v;
    }
  };
  const int triangle_count = static_cast<int>(surface.triangles.rows());
  triangles_.resize(triangle_count);
  triangle_grown_.resize(triangle_count);
  extents_.resize(triangle_count);
  for (int t = 0; t < triangle_count; ++t) {
    double seed;
    feature({surface.triangles(t, 0), surface.triangles(t, 1), surface.triangles(t, 2)},
            triangles_[t], seed);
    triangle_grown_[t] = grown(triangles_[t].box, seed);
    extents_[t] = triangle_grown_[t].sizes().maxCoeff();
  }
  const int edge_count = static_cast<int>(surface.edges.rows());
  edges_.resize(edge_count);
  edge_grown_.resize(edge_count);
  for (int e = 0; e < edge_count; ++e) {
    double seed;
    feature({surface.edges(e, 0), surface.edges(e, 1)}, edges_[e], seed);
    edge_grown_[e] = grown(edges_[e].box, seed);
  }
}

void SelfContactProximity::seed_vertex(int v) {
  // 2R_v, or less where a triangle across the far edge ab of one of v's triangles makes a found
  // pair with v: that triangle holds ab, so it is no farther than ab is.
  const SelfCollisionSurface& surface = *surface_;
  const Eigen::Vector3d& p = points_[v];
  double seed = 2.0 * reach_[v];
  for (int k = surface.vertex_triangles.begin(v); k < surface.vertex_triangles.end(v); ++k) {
    const int t = surface.vertex_triangles.ids[k];
    int a = surface.triangles(t, 0), b = surface.triangles(t, 1);
    if (a == v) a = surface.triangles(t, 2);
    if (b == v) b = surface.triangles(t, 2);
    if (a == b || !has_triangle_across(surface, a, b, t, v)) continue;
    const Eigen::Vector3d &xa = points_[a], &xb = points_[b];
    Eigen::AlignedBox3d side(xa);
    side.extend(xb);
    const double r = reach_[v] + std::max(reach_[a], reach_[b]);
    if (!(box_gap(Eigen::AlignedBox3d(p), side) <= r).all()) continue;
    const Eigen::Vector3d along = xb - xa;
    const double length2 = along.squaredNorm();
    const double s = length2 > 0.0 ? std::clamp((p - xa).dot(along) / length2, 0.0, 1.0) : 0.0;
    seed = std::min(seed, (p - xa - s * along).norm());
  }
  seed_[v] = seed;
}

void SelfContactProximity::query_vertex(int v, Chunk& chunk) {
  const Eigen::Vector3d& p = points_[v];
  const Eigen::AlignedBox3d point(p);
  const double r = reach_[v], c2 = contact_distance_ * contact_distance_;
  const Eigen::AlignedBox3d box = grown(point, std::max(seed_[v], 0.5 * contact_distance_));
  double own = nearest(v);  // never below v's shared value, so safe to skip against
  if (chunk.kept.empty()) chunk.kept.resize(1);
  int met = 0;
  triangle_grid_.for_each_overlapping(box, [&](int t) {
    if (++met > max_met) {
      chunk.frozen.push_back(box);
      return false;
    }
    const Feature& triangle = triangles_[t];
    const int a = triangle.vertex[0], b = triangle.vertex[1], c = triangle.vertex[2];
    if (v == a || v == b || v == c) return true;
    const Eigen::Array3d gap = box_gap(point, triangle.box);
    const bool found = (gap <= r + triangle.reach).all();
    const double low2 = gap.matrix().squaredNorm();  // the distance is no less than its root
    if (!(low2 < c2)) {
      if (!found) return true;
      const double limit = std::max(std::max(own, nearest(a)), std::max(nearest(b), nearest(c)));
      if (low2 >= limit * limit) return true;
    }
    const Eigen::Vector3d &xa = points_[a], &xb = points_[b], &xc = points_[c];
    const Eigen::Vector3d alpha = closest_on_triangle(p, xa, xb, xc);
    const Eigen::Vector3d q = p - alpha(0) * xa - alpha(1) * xb - alpha(2) * xc;
    const double distance = q.norm();
    if (found) {
      own = std::min(own, distance);
      lower(a, distance);
      lower(b, distance);
      lower(c, distance);
    }
    if (distance * distance < c2 && !rest_->vertex_triangle(v, t)) {
      SelfContactPair pair{{v, a, b, c}, {1.0, -alpha(0), -alpha(1), -alpha(2)}, {}, 0.0, distance,
                           true};
      pair.normal = distance > 0.0 ? Eigen::Vector3d(q / distance)
                                   : touching_normal((xb - xa).cross(xc - xa), xb - xa);
      stage(pair, distance, chunk.kept[0]);
    }
    return true;
  });
  lower(v, own);
  commit(chunk.kept[0], chunk.pairs);
}

void SelfContactProximity::query_edges(int v, Chunk& chunk) {
  // The edges whose lower vertex is v, in one look at the grid over their boxes' union: they
  // overlap, so that costs much less than a look for each.
  const CompressedRows& rows = surface_->vertex_edges;
  chunk.owned.clear();
  chunk.ends.clear();
  Eigen::AlignedBox3d box;
  for (int k = rows.begin(v); k < rows.end(v); ++k) {
    const int e = rows.ids[k];  // ascending
    if (edges_[e].vertex[0] != v) continue;
    chunk.owned.push_back(e);
    chunk.ends.push_back(nearest(edges_[e].vertex[1]));
    box.extend(edge_grown_[e]);
  }
  const int count = static_cast<int>(chunk.owned.size());
  if (count == 0) return;
  if (static_cast<int>(chunk.kept.size()) < count) chunk.kept.resize(count);
  double own = nearest(v);
  int met = 0;
  edge_grid_.for_each_overlapping(box, [&](int f) {
    if (++met > max_met) {
      chunk.frozen.push_back(box);
      return false;
    }
    // Each pair once, from its lower edge.
    for (int k = 0; k < count && chunk.owned[k] < f; ++k)
      examine_edges(chunk.owned[k], f, own, chunk.ends[k], chunk.kept[k]);
    return true;
  });
  lower(v, own);
  for (int k = 0; k < count; ++k) {
    lower(edges_[chunk.owned[k]].vertex[1], chunk.ends[k]);
    commit(chunk.kept[k], chunk.pairs);
  }
}

void SelfContactProximity::examine_edges(int e, int f, double& own0, double& own1, Kept& kept) {
  const Feature &edge = edges_[e], &other = edges_[f];
  const int p0 = edge.vertex[0], p1 = edge.vertex[1], q0 = other.vertex[0], q1 = other.vertex[1];
  if (q0 == p0 || q0 == p1 || q1 == p0 || q1 == p1) return;
  const Eigen::Array3d gap = box_gap(edge.box, other.box);
  const bool found = (gap <= edge.reach + other.reach).all();
  const double low2 = gap.matrix().squaredNorm();  // the distance is no less than its root
  const double c2 = contact_distance_ * contact_distance_;
  if (!(low2 < c2)) {
    if (!found) return;
    // Too far to lower any of the four: no exact distance needed.
    const double limit = std::max(std::max(own0, own1), std::max(nearest(q0), nearest(q1)));
    if (low2 >= limit * limit) return;
  }
  const Eigen::Vector3d &x0 = points_[p0], &x1 = points_[p1], &y0 = points_[q0], &y1 = points_[q1];
  const Eigen::Vector2d su = closest_on_segments(x0, x1, y0, y1);
  const Eigen::Vector3d q = (1.0 - su(0)) * x0 + su(0) * x1 - (1.0 - su(1)) * y0 - su(1) * y1;
  const double distance = q.norm();
  if (found) {
    own0 = std::min(own0, distance);
    own1 = std::min(own1, distance);
    lower(q0, distance);
    lower(q1, distance);
  }
  if (distance * distance < c2 && !rest_->edge_edge(e, f)) {
    SelfContactPair pair{
        {p0, p1, q0, q1}, {1.0 - su(0), su(0), -(1.0 - su(1)), -su(1)}, {}, 0.0, distance, false};
    pair.normal = distance > 0.0 ? Eigen::Vector3d(q / distance)
                                 : touching_normal((x1 - x0).cross(y1 - y0), x1 - x0);
    stage(pair, distance, kept);
  }
}

void SelfContactProximity::stage(const SelfContactPair& pair, double distance, Kept& kept) const {
  // A max-heap of the nearest so far; a tie keeps the one met first (the grid's order, which
  // does not depend on the threads).
  if (static_cast<int>(kept.near.size()) < max_pairs_per_feature) {
    kept.near.emplace_back(distance, static_cast<int>(kept.staged.size()));
    kept.staged.push_back(pair);
    std::push_heap(kept.near.begin(), kept.near.end());
    return;
  }
  if (!(distance < kept.near.front().first)) return;
  std::pop_heap(kept.near.begin(), kept.near.end());
  const int slot = kept.near.back().second;
  kept.staged[slot] = pair;
  kept.near.back() = {distance, slot};
  std::push_heap(kept.near.begin(), kept.near.end());
}

void SelfContactProximity::commit(Kept& kept, std::vector<SelfContactPair>& pairs) const {
  // In the order of the other feature's vertices, as self_contact_detection.cpp does: whatever
  // order the grid met them in, a consumer's sweeps do the same on any grid.
  const auto other = [&](const std::pair<double, int>& near) {
    const SelfContactPair& pair = kept.staged[near.second];
    return std::make_tuple(pair.vertex[1], pair.vertex[2], pair.vertex[3]);
  };
  std::sort(kept.near.begin(), kept.near.end(),
            [&](const auto& a, const auto& b) { return other(a) < other(b); });
  for (const auto& near : kept.near)
    pairs.push_back(kept.staged[near.second]);
  kept.near.clear();
  kept.staged.clear();
}

void SelfContactProximity::freeze_near_saturated_queries(double cell) {
  // Every pair a stopped query may have left unexamined has its other feature's grown box
  // overlapping the query box, and that feature lies in a triangle whose grown box holds its
  // own. Freezing the vertices of all such triangles freezes both sides of each such pair (the
  // querying vertex or edge lies in such a triangle too).
  const SelfCollisionSurface& surface = *surface_;
  frozen_grid_.build(frozen_boxes_, cell);
  const int triangle_count = static_cast<int>(surface.triangles.rows());
  triangle_frozen_.resize(triangle_count);
  auto task = [&](int piece) {
    const int first =
        static_cast<int>(static_cast<long long>(triangle_count) * piece / chunks_per_kind);
    const int last =
        static_cast<int>(static_cast<long long>(triangle_count) * (piece + 1) / chunks_per_kind);
    for (int t = first; t < last; ++t) {
      bool frozen = false;
      frozen_grid_.for_each_overlapping(triangle_grown_[t], [&](int) {
        frozen = true;
        return false;
      });
      triangle_frozen_[t] = frozen;
    }
  };
  pool().run(chunks_per_kind, task, &frozen_payoff_);
  for (int t = 0; t < triangle_count; ++t) {
    if (!triangle_frozen_[t]) continue;
    for (int c = 0; c < 3; ++c)
      nearest_[surface.triangles(t, c)].store(0.0, std::memory_order_relaxed);
  }
}

std::size_t SelfContactProximity::memory_bytes() const {
  std::size_t bytes =
      points_.capacity() * sizeof(Eigen::Vector3d) +
      (reach_.capacity() + seed_.capacity() + extents_.capacity() + nearest_capacity_) *
          sizeof(double) +
      (triangles_.capacity() + edges_.capacity()) * sizeof(Feature) +
      (triangle_grown_.capacity() + edge_grown_.capacity() + frozen_boxes_.capacity()) *
          sizeof(Eigen::AlignedBox3d) +
      triangle_frozen_.capacity() + triangle_grid_.memory_bytes() + edge_grid_.memory_bytes() +
      frozen_grid_.memory_bytes();
  for (const Chunk& chunk : chunks_) {
    bytes += chunk.pairs.capacity() * sizeof(SelfContactPair) +
             chunk.frozen.capacity() * sizeof(Eigen::AlignedBox3d) +
             chunk.owned.capacity() * sizeof(int) + chunk.ends.capacity() * sizeof(double);
    for (const Kept& kept : chunk.kept) {
      bytes += kept.staged.capacity() * sizeof(SelfContactPair) +
               kept.near.capacity() * sizeof(std::pair<double, int>);
    }
  }
  return bytes;
}

int clamp_to_bounds(const Eigen::MatrixXd& x, const Eigen::Vector3d& common,
                    const Eigen::VectorXd& bounds, Eigen::MatrixXd& p) {
  int moved = 0;
  const Eigen::Index n = std::min<Eigen::Index>(bounds.size(), std::min(x.rows(), p.rows()));
  for (Eigen::Index v = 0; v < n; ++v) {
    double bound = bounds(v);
    if (bound == infinity) continue;
    if (!(bound >= 0.0)) bound = 0.0;
    const Eigen::Vector3d start = vertex_row(x, static_cast<int>(v)) + common;
    const Eigen::Vector3d relative = vertex_row(p, static_cast<int>(v)) - start;
    const double length = relative.norm();
    if (length <= bound) continue;
    // Scaled a hair inside the bound, so that rounding cannot put it just past.
    const double scale = std::isfinite(length) ? bound / length * (1.0 - 1e-12) : 0.0;
    p.row(v) = (start + scale * relative).transpose();
    ++moved;
  }
  return moved;
}

}  // namespace wobble

#include "sim/contact/self_contact_proximity.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/contact/vertex_row.h"

namespace wobble {

namespace {

// The queries are cut into this many chunks a kind, whatever the thread count, so that the
// pairs come out in the same order on any machine.
constexpr int chunks_per_kind = 64;

constexpr double infinity = std::numeric_limits<double>::infinity();

// The value a quarter of `values` are above (0 for none); reorders them.
double upper_quartile(std::vector<double>& values) {
  if (values.empty()) return 0.0;
  const auto at = values.begin() + static_cast<std::ptrdiff_t>(3 * values.size() / 4);
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

struct Range {
  int first, last;
};
// Piece `piece` of chunks_per_kind of [0, count).
Range chunk_range(int count, int piece) {
  const long long n = count;
  return {static_cast<int>(n * piece / chunks_per_kind),
          static_cast<int>(n * (piece + 1) / chunks_per_kind)};
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

}  // namespace

void SelfContactProximity::find(const SelfCollisionSurface& surface, const RestNeighbours& rest,
                                const Eigen::MatrixXd& x, const Eigen::VectorXd& reach,
                                double contact_distance, std::vector<SelfContactPair>& pairs,
                                Eigen::VectorXd& bounds) {
  surface_ = &surface;
  rest_ = &rest;
  contact_distance_ = contact_distance > 0.0 ? contact_distance : 0.0;
  prepare(x, reach);
  const int vertex_count = static_cast<int>(surface.vertices.size());
  // The closest any two features may come: far above the rounding of the coordinates (else a
  // pair pressed together, its bounds shrinking with its distance, comes within rounding of
  // touching, and rounding alone carries an edge through a triangle), far below the thickness.
  double magnitude = 0.0;
  for (const int v : surface.vertices)
    magnitude = std::max(magnitude, points_[v].cwiseAbs().maxCoeff());
  floor_ = std::max(separation_share * contact_distance_,
                    rounding_margin * std::numeric_limits<double>::epsilon() * magnitude);

  // A pair can lower no bound unless it is closer than the largest of its vertices' needs (the
  // seeds, an upper bound on each nearest), and is listed only closer than the contact distance:
  // the query box and the box in the grid must together grow by that much. The query side takes
  // a common floor W (most needs, and the contact distance), the grid side only a need's excess
  // over W: most boxes in the grid stay bare, and a query meets far fewer than with both grown.
  scratch_.clear();
  for (const int v : surface.vertices)
    scratch_.push_back(need_[v]);
  vertex_floor_ = std::max(contact_distance_, upper_quartile(scratch_));
  const int triangle_count = static_cast<int>(triangles_.size());
  const auto filed_triangle = [&](int t) { return filed(triangles_[t], vertex_floor_); };
  scratch_.resize(triangle_count);
  for (int t = 0; t < triangle_count; ++t)
    scratch_[t] = filed_triangle(t).sizes().maxCoeff();
  // Cells about the size of the upper quartile of the boxes: a query box, grown by the floor,
  // spans a few boxes, and smaller cells leave a query looking at many empty cells (a sheet fills
  // few cells of a 3D grid): docs/performance.md, "Contact's weight and the self-contact grid".
  double cell = std::max(surface.mean_edge, contact_distance_);
  const double typical = upper_quartile(scratch_);
  if (std::isfinite(typical) && typical > 0.0) cell = typical;
  cell *= cell_per_box;
  triangle_grid_.build(triangle_count, filed_triangle, cell);

  chunks_.resize(2 * chunks_per_kind);
  const auto run = [&](bool vertices) {
    auto task = [&](int piece) {
      Chunk& chunk = chunks_[vertices ? piece : chunks_per_kind + piece];
      chunk.pairs.clear();
      chunk.frozen.clear();
      const Range range = chunk_range(vertex_count, piece);
      for (int k = range.first; k < range.last; ++k) {
        if (vertices) {
          query_vertex(surface.vertices[k], chunk);
        } else {
          query_edges(surface.vertices[k], chunk);
        }
      }
    };
    pool().run(chunks_per_kind, task, vertices ? &vertex_payoff_ : &edge_payoff_);
  };
  run(true);

  // The vertex-triangle pairs have lowered the needs (in a pile, to the next layer's distance):
  // the edges search with those, taken now so that no query depends on another's timing.
  const int edge_count = static_cast<int>(edges_.size());
  scratch_.clear();
  for (const int v : surface.vertices)
    scratch_.push_back(nearest(v));
  edge_floor_ = std::max(contact_distance_, upper_quartile(scratch_));
  for (const int v : surface.vertices)
    need_[v] = nearest(v);
  const auto filed_edge = [&](int e) { return filed(edges_[e], edge_floor_); };
  edge_grid_.build(edge_count, filed_edge, cell);
  run(false);

  pairs.clear();
  frozen_boxes_.clear();
  for (const Chunk& chunk : chunks_) {
    pairs.insert(pairs.end(), chunk.pairs.begin(), chunk.pairs.end());
    frozen_boxes_.insert(frozen_boxes_.end(), chunk.frozen.begin(), chunk.frozen.end());
  }
  saturated_ = !frozen_boxes_.empty();
  if (saturated_) freeze_near_saturated_queries(cell);

  bounds.setConstant(x.rows(), infinity);
  under_floor_ = false;
  for (const int v : surface.vertices) {
    bounds(v) = 0.5 * bound_fraction * std::max(nearest(v) - floor_, 0.0);
    under_floor_ = under_floor_ || nearest(v) < floor_;
  }
}

Eigen::AlignedBox3d SelfContactProximity::box(const Feature& feature) const {
  Eigen::AlignedBox3d box(points_[feature.vertex[0]]);
  box.extend(points_[feature.vertex[1]]);
  if (feature.vertex[2] >= 0) box.extend(points_[feature.vertex[2]]);
  return box;
}

double SelfContactProximity::need(const Feature& feature) const {
  double most = std::max(need_[feature.vertex[0]], need_[feature.vertex[1]]);
  if (feature.vertex[2] >= 0) most = std::max(most, need_[feature.vertex[2]]);
  return most;
}

void SelfContactProximity::prepare(const Eigen::MatrixXd& x, const Eigen::VectorXd& reach) {
  const SelfCollisionSurface& surface = *surface_;
  const int n = static_cast<int>(x.rows());
  pack_rows(x, points_);
  Eigen::AlignedBox3d whole;
  for (const int v : surface.vertices)
    whole.extend(points_[v]);
  const double largest = whole.isEmpty() ? 0.0 : whole.diagonal().norm();
  reach_.assign(n, 0.0);
  for (const int v : surface.vertices) {
    const double r = v < reach.size() ? reach(v) : 0.0;
    reach_[v] = r > 0.0 ? std::min(r, largest) : 0.0;
  }
  const auto feature = [&](std::initializer_list<int> vertices) {
    double most = 0.0;
    Feature f{0.0f, {-1, -1, -1}};
    int k = 0;
    for (const int v : vertices) {
      most = std::max(most, reach_[v]);
      f.vertex[k++] = v;
    }
    f.reach = SpatialGrid::above(most);
    return f;
  };
  triangles_.resize(surface.triangles.rows());
  for (std::size_t t = 0; t < triangles_.size(); ++t)
    triangles_[t] =
        feature({surface.triangles(t, 0), surface.triangles(t, 1), surface.triangles(t, 2)});
  edges_.resize(surface.edges.rows());
  for (std::size_t e = 0; e < edges_.size(); ++e)
    edges_[e] = feature({surface.edges(e, 0), surface.edges(e, 1)});

  need_.resize(n);
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
    nearest_[v].store(need_[v], std::memory_order_relaxed);
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
  need_[v] = seed;
}

void SelfContactProximity::freeze_near_saturated_queries(double cell) {
  // Every pair a stopped query may have left unexamined has its other feature's box in the grid
  // overlapping the query box. Freezing the vertices of every triangle and edge whose box in the
  // grid overlaps a stopped query's box freezes both sides of each such pair (the querying
  // vertex or edges lie in such boxes too).
  frozen_grid_.build(frozen_boxes_, cell);
  const int triangle_count = static_cast<int>(triangles_.size());
  const int feature_count = triangle_count + static_cast<int>(edges_.size());
  feature_frozen_.assign(feature_count, 0);
  const int triangles_filed = triangle_grid_.filed_count();
  const int filed = triangles_filed + edge_grid_.filed_count();
  auto task = [&](int piece) {
    const Range range = chunk_range(filed, piece);
    for (int k = range.first; k < range.last; ++k) {
      // The box as filed (each feature's k is its own: no two tasks write the same flag).
      const bool triangle = k < triangles_filed;
      const std::pair<int, Eigen::AlignedBox3f> entry =
          triangle ? triangle_grid_.filed(k) : edge_grid_.filed(k - triangles_filed);
      const int flag = triangle ? entry.first : triangle_count + entry.first;
      frozen_grid_.for_each_overlapping(entry.second.cast<double>(), [&](int) {
        feature_frozen_[flag] = 1;
        return false;
      });
    }
  };
  pool().run(chunks_per_kind, task, &frozen_payoff_);
  for (int k = 0; k < feature_count; ++k) {
    if (!feature_frozen_[k]) continue;
    const Feature& feature = k < triangle_count ? triangles_[k] : edges_[k - triangle_count];
    for (const int v : feature.vertex) {
      if (v >= 0) nearest_[v].store(0.0, std::memory_order_relaxed);
    }
  }
}

std::size_t SelfContactProximity::memory_bytes() const {
  std::size_t bytes =
      points_.capacity() * sizeof(Eigen::Vector3d) +
      (reach_.capacity() + need_.capacity() + scratch_.capacity() + nearest_capacity_) *
          sizeof(double) +
      (triangles_.capacity() + edges_.capacity()) * sizeof(Feature) +
      frozen_boxes_.capacity() * sizeof(Eigen::AlignedBox3d) + feature_frozen_.capacity() +
      triangle_grid_.memory_bytes() + edge_grid_.memory_bytes() + frozen_grid_.memory_bytes();
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

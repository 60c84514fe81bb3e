#include "sim/contact/self_contact_detection.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "sim/contact/closest_points.h"
#include "sim/contact/vertex_row.h"

namespace wobble {

namespace {

// The queries are cut into this many chunks a kind, whatever the thread count, so that the
// pairs come out in the same order on any machine.
constexpr int chunks_per_kind = 32;

}  // namespace

void SelfContactDetection::detect(const SelfCollisionSurface& surface, const RestNeighbours& rest,
                                  const Eigen::MatrixXd& start, const Eigen::MatrixXd& end,
                                  double thickness, double margin,
                                  std::vector<SelfContactPair>& pairs) {
  surface_ = &surface;
  rest_ = &rest;
  start_ = &start;
  end_ = &end;
  thickness_ = thickness;
  margin_ = margin;

  // The common motion, and each vertex's wander from it.
  mean_motion_.setZero();
  for (const int v : surface.vertices)
    mean_motion_ += vertex_row(end, v) - vertex_row(start, v);
  if (!surface.vertices.empty()) mean_motion_ /= static_cast<double>(surface.vertices.size());
  wander_.assign(start.rows(), 0.0);
  for (const int v : surface.vertices)
    wander_[v] = (vertex_row(end, v) - vertex_row(start, v) - mean_motion_).norm();

  // Each vertex's path in the frame that moves with ū: from where it starts to where it ends
  // less the common motion. Two features come within the thickness only where their paths in
  // that frame do, so each box covers its vertices' paths there (long and thin along a fold's
  // fall, not a ball of the wander's radius).
  const auto swept = [&](int i) {
    const Eigen::Vector3d from = vertex_row(start, i);
    Eigen::AlignedBox3d box(from);
    box.extend(Eigen::Vector3d(vertex_row(end, i) - mean_motion_));
    return box;
  };
  const double grow = 0.5 * thickness + margin;
  const int triangle_count = static_cast<int>(surface.triangles.rows());
  triangle_boxes_.resize(triangle_count);
  extents_.resize(triangle_count);
  for (int t = 0; t < triangle_count; ++t) {
    Eigen::AlignedBox3d box;
    for (int c = 0; c < 3; ++c)
      box.extend(swept(surface.triangles(t, c)));
    box.min().array() -= grow;
    box.max().array() += grow;
    triangle_boxes_[t] = box;
    extents_[t] = box.sizes().maxCoeff();
  }
  const int edge_count = static_cast<int>(surface.edges.rows());
  edge_boxes_.resize(edge_count);
  for (int e = 0; e < edge_count; ++e) {
    const int i = surface.edges(e, 0), j = surface.edges(e, 1);
    Eigen::AlignedBox3d box = swept(i);
    box.extend(swept(j));
    box.min().array() -= grow;
    box.max().array() += grow;
    edge_boxes_[e] = box;
  }
  // Cells the size of most boxes: each box covers a few cells, each cell holds a few boxes.
  double cell = std::max(surface.mean_edge, thickness + 2.0 * margin);
  if (!extents_.empty()) {
    const auto quartile = extents_.begin() + static_cast<std::ptrdiff_t>(3 * extents_.size() / 4);
    std::nth_element(extents_.begin(), quartile, extents_.end());
    if (std::isfinite(*quartile)) cell = std::max(cell, *quartile);
  }
  triangle_grid_.build(triangle_boxes_, cell);
  edge_grid_.build(edge_boxes_, cell);

  chunks_.resize(2 * chunks_per_kind);
  const int vertex_count = static_cast<int>(surface.vertices.size());
  auto task = [&](int index) {
    Chunk& chunk = chunks_[index];
    chunk.pairs.clear();
    chunk.saturated = false;
    const int piece = index % chunks_per_kind;
    if (index < chunks_per_kind) {
      const int first =
          static_cast<int>(static_cast<long long>(vertex_count) * piece / chunks_per_kind);
      const int last =
          static_cast<int>(static_cast<long long>(vertex_count) * (piece + 1) / chunks_per_kind);
      for (int k = first; k < last; ++k)
        query_vertex(surface.vertices[k], chunk);
    } else {
      const int first =
          static_cast<int>(static_cast<long long>(edge_count) * piece / chunks_per_kind);
      const int last =
          static_cast<int>(static_cast<long long>(edge_count) * (piece + 1) / chunks_per_kind);
      for (int e = first; e < last; ++e)
        query_edge(e, chunk);
    }
  };
  WorkerPool::shared().run(2 * chunks_per_kind, task, &payoff_);
  pairs.clear();
  saturated_ = false;
  for (int k = 0; k < 2 * chunks_per_kind; ++k) {
    const Chunk& chunk = chunks_[(k + chunks_per_kind) % (2 * chunks_per_kind)];
    saturated_ = saturated_ || chunk.saturated;
    pairs.insert(pairs.end(), chunk.pairs.begin(), chunk.pairs.end());
  }
}

void SelfContactDetection::query_vertex(int v, Chunk& chunk) const {
  const SelfCollisionSurface& surface = *surface_;
  const Eigen::MatrixXd& start = *start_;
  const Eigen::Vector3d p = vertex_row(start, v);
  Eigen::AlignedBox3d box(p);
  box.extend(Eigen::Vector3d(vertex_row(*end_, v) - mean_motion_));
  const double grow = 0.5 * thickness_ + margin_;
  box.min().array() -= grow;
  box.max().array() += grow;
  chunk.staged.clear();
  int examined = 0;
  int met = 0;
  triangle_grid_.for_each_overlapping(box, [&](int t) {
    // Boxes skipped below count too, at a looser bound: coincident features stay bounded.
    if (++met > max_met) {
      chunk.saturated = true;
      return false;
    }
    const int a = surface.triangles(t, 0), b = surface.triangles(t, 1), c = surface.triangles(t, 2);
    if (v == a || v == b || v == c || rest_->vertex_triangle(v, t)) return true;
    const Eigen::Vector3d alpha =
        closest_on_triangle(p, vertex_row(start, a), vertex_row(start, b), vertex_row(start, c));
    keep_if_close(
        SelfContactPair{{v, a, b, c}, {1.0, -alpha(0), -alpha(1), -alpha(2)}, {}, 0.0, 0.0, true},
        1, chunk);
    if (++examined < max_examined) return true;
    chunk.saturated = true;
    return false;
  });
  commit(chunk);
}

void SelfContactDetection::query_edge(int e, Chunk& chunk) const {
  const SelfCollisionSurface& surface = *surface_;
  const Eigen::MatrixXd& start = *start_;
  const int p0 = surface.edges(e, 0), p1 = surface.edges(e, 1);
  chunk.staged.clear();
  int examined = 0;
  int met = 0;
  edge_grid_.for_each_overlapping(edge_boxes_[e], [&](int f) {
    if (++met > max_met) {
      chunk.saturated = true;
      return false;
    }
    if (f <= e) return true;  // each pair once, from its lower edge
    const int q0 = surface.edges(f, 0), q1 = surface.edges(f, 1);
    if (q0 == p0 || q0 == p1 || q1 == p0 || q1 == p1 || rest_->edge_edge(e, f)) return true;
    const Eigen::Vector2d su = closest_on_segments(vertex_row(start, p0), vertex_row(start, p1),
                                                   vertex_row(start, q0), vertex_row(start, q1));
    keep_if_close(
        SelfContactPair{
            {p0, p1, q0, q1}, {1.0 - su(0), su(0), -(1.0 - su(1)), -su(1)}, {}, 0.0, 0.0, false},
        2, chunk);
    if (++examined < max_examined) return true;
    chunk.saturated = true;
    return false;
  });
  commit(chunk);
}

void SelfContactDetection::keep_if_close(SelfContactPair pair, int first_size, Chunk& chunk) const {
  const Eigen::MatrixXd& start = *start_;
  const Eigen::MatrixXd& end = *end_;
  const double h = thickness_;
  Eigen::Vector3d gap = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k)
    gap += pair.beta[k] * vertex_row(start, pair.vertex[k]);
  const double distance = gap.norm();
  // How much closer the motion can bring the two features. Each point of one moves relative to
  // the other by a convex mix of its vertices' motions, so by at most the largest of them
  // relative to the pair's first vertex, or the sum of the two features' largest wander.
  // Tighter still, across the plane through the closest points, which separates the features
  // (each lies on its side): the first can come down it by at most its vertices' largest motion
  // against the normal, the second up it by their largest along it, both taken relative to the
  // pair's mean motion (the distance does not change when all four move alike), so sliding
  // along the layers and a fold turning about its crease count only for what they bring across.
  Eigen::Vector3d motion[4], mean = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k) {
    motion[k] = vertex_row(end, pair.vertex[k]) - vertex_row(start, pair.vertex[k]);
    mean += 0.25 * motion[k];
  }
  double closing_first = 0.0, closing_second = 0.0, wander_first = 0.0, wander_second = 0.0;
  double down_first = 0.0, up_second = 0.0;
  const Eigen::Vector3d across =
      distance > 1e-9 * h ? Eigen::Vector3d(gap / distance) : Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k) {
    const double moved = (motion[k] - motion[0]).norm();
    const double along = across.dot(motion[k] - mean);
    if (k < first_size) {
      closing_first = std::max(closing_first, moved);
      wander_first = std::max(wander_first, wander_[pair.vertex[k]]);
      down_first = std::max(down_first, -along);
    } else {
      closing_second = std::max(closing_second, moved);
      wander_second = std::max(wander_second, wander_[pair.vertex[k]]);
      up_second = std::max(up_second, along);
    }
  }
  double closing = std::min(closing_first + closing_second, wander_first + wander_second);
  if (distance > 1e-9 * h) closing = std::min(closing, down_first + up_second);
  if (!(distance - closing < h + 2.0 * margin_)) return;
  if (distance > 1e-9 * h) {
    pair.normal = gap / distance;
  } else {
    // Touching at the start (nothing kept them apart): the normal of the two features' plane,
    // on the side the pair ends on.
    pair.normal = (vertex_row(start, pair.vertex[1]) - vertex_row(start, pair.vertex[0]))
                      .cross(vertex_row(start, pair.vertex[3]) - vertex_row(start, pair.vertex[2]));
    if (!(pair.normal.squaredNorm() > 0.0)) return;
    pair.normal.normalize();
    Eigen::Vector3d at_end = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k)
      at_end += pair.beta[k] * vertex_row(end, pair.vertex[k]);
    if (at_end.dot(pair.normal) < 0.0) pair.normal = -pair.normal;
  }
  // A pair that starts closer than the thickness (the last step's sweeps left it short, or two
  // layers were made that close) opens by at most a fraction of it a step.
  pair.target = std::min(h, std::max(distance, 0.0) + recovery_fraction * h);
  chunk.near.emplace_back(distance - closing, static_cast<int>(chunk.staged.size()));
  chunk.staged.push_back(pair);
}

void SelfContactDetection::commit(Chunk& chunk) const {
  if (static_cast<int>(chunk.near.size()) > max_pairs_per_feature) {
    chunk.saturated = true;
    std::nth_element(chunk.near.begin(), chunk.near.begin() + max_pairs_per_feature,
                     chunk.near.end());
    chunk.near.resize(max_pairs_per_feature);
  }
  // In the order of the other feature's vertices, whatever order the grid found them in: the
  // response's Gauss-Seidel sweeps then do the same on any grid.
  const auto other = [&](const std::pair<double, int>& kept) {
    const SelfContactPair& pair = chunk.staged[kept.second];
    return std::make_tuple(pair.vertex[1], pair.vertex[2], pair.vertex[3]);
  };
  std::sort(chunk.near.begin(), chunk.near.end(),
            [&](const auto& a, const auto& b) { return other(a) < other(b); });
  for (const auto& kept : chunk.near)
    chunk.pairs.push_back(chunk.staged[kept.second]);
  chunk.near.clear();
  chunk.staged.clear();
}

std::size_t SelfContactDetection::memory_bytes() const {
  std::size_t bytes =
      (wander_.capacity() + extents_.capacity()) * sizeof(double) +
      (triangle_boxes_.capacity() + edge_boxes_.capacity()) * sizeof(Eigen::AlignedBox3d) +
      triangle_grid_.memory_bytes() + edge_grid_.memory_bytes();
  for (const Chunk& chunk : chunks_)
    bytes += (chunk.pairs.capacity() + chunk.staged.capacity()) * sizeof(SelfContactPair) +
             chunk.near.capacity() * sizeof(std::pair<double, int>);
  return bytes;
}

}  // namespace wobble

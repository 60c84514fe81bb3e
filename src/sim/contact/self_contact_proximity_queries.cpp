#include "sim/contact/self_contact_proximity.h"

#include <algorithm>
#include <tuple>

#include "sim/contact/closest_points.h"

// The queries of SelfContactProximity::find: a vertex against the triangles, a vertex's edges
// against the higher-numbered edges, and the nearest pairs each feature keeps.

namespace wobble {

namespace {

// A normal for two features that touch: the first of these that has a direction.
Eigen::Vector3d touching_normal(const Eigen::Vector3d& across, const Eigen::Vector3d& along) {
  if (across.squaredNorm() > 0.0) return across.normalized();
  if (along.squaredNorm() > 0.0) return along.unitOrthogonal();
  return Eigen::Vector3d::UnitZ();
}

}  // namespace

void SelfContactProximity::query_vertex(int v, Chunk& chunk) {
  const Eigen::Vector3d& p = points_[v];
  const Eigen::AlignedBox3d point(p);
  const double r = reach_[v], c2 = contact_distance_ * contact_distance_;
  const Eigen::AlignedBox3d query = grown(point, std::max(need_[v], vertex_floor_));
  double own = nearest(v);  // never below v's shared value, so safe to skip against
  if (chunk.kept.empty()) chunk.kept.resize(1);
  int met = 0;
  triangle_grid_.for_each_overlapping(query, [&](int t, const Eigen::AlignedBox3f& filed) {
    if (++met > max_met) {
      chunk.frozen.push_back(query);
      return false;
    }
    const Feature& triangle = triangles_[t];
    const int a = triangle.vertex[0], b = triangle.vertex[1], c = triangle.vertex[2];
    if (v == a || v == b || v == c) return true;
    const Eigen::Array3d gap = box_gap(point, filed.cast<double>());
    const bool found = (gap <= r + static_cast<double>(triangle.reach)).all();
    const double low2 = gap.matrix().squaredNorm();  // the distance is no less than its root
    // The exact distance only where it can lower a bound or make a pair (the rest shape's own
    // neighbours within the contact distance are many, and mostly too far for the bounds).
    const double limit = std::max(std::max(own, nearest(a)), std::max(nearest(b), nearest(c)));
    const bool for_bounds = found && low2 < limit * limit;
    // Whether a pair in the rest shape too, asked only where it decides something.
    const auto at_rest = [&] { return rest_->vertex_triangle(*surface_, v, t); };
    const bool may_pair = low2 < c2 && (for_bounds || !at_rest());
    if (!for_bounds && !may_pair) return true;
    const Eigen::Vector3d &xa = points_[a], &xb = points_[b], &xc = points_[c];
    const Eigen::Vector3d alpha = closest_on_triangle(p, xa, xb, xc);
    const Eigen::Vector3d q = p - alpha(0) * xa - alpha(1) * xb - alpha(2) * xc;
    const double distance = q.norm();
    if (for_bounds) {
      own = std::min(own, distance);
      lower(a, distance);
      lower(b, distance);
      lower(c, distance);
    }
    if (may_pair && distance * distance < c2 && !(for_bounds && at_rest())) {
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
  chunk.boxes.clear();
  chunk.ends.clear();
  Eigen::AlignedBox3d query;
  for (int k = rows.begin(v); k < rows.end(v); ++k) {
    const int e = rows.ids[k];  // ascending
    if (edges_[e].vertex[0] != v) continue;
    chunk.owned.push_back(e);
    chunk.boxes.push_back(box(edges_[e]));
    chunk.ends.push_back(nearest(edges_[e].vertex[1]));
    query.extend(grown(chunk.boxes.back(), std::max(need(edges_[e]), edge_floor_)));
  }
  const int count = static_cast<int>(chunk.owned.size());
  if (count == 0) return;
  if (static_cast<int>(chunk.kept.size()) < count) chunk.kept.resize(count);
  double own = nearest(v);
  int met = 0;
  edge_grid_.for_each_overlapping(query, [&](int f, const Eigen::AlignedBox3f& filed) {
    if (++met > max_met) {
      chunk.frozen.push_back(query);
      return false;
    }
    // Each pair once, from its lower edge.
    if (chunk.owned[0] >= f) return true;
    const Eigen::AlignedBox3d f_box = filed.cast<double>();
    for (int k = 0; k < count && chunk.owned[k] < f; ++k) {
      examine_edges(chunk.owned[k], chunk.boxes[k], f, f_box, own, chunk.ends[k], chunk.kept[k]);
    }
    return true;
  });
  lower(v, own);
  for (int k = 0; k < count; ++k) {
    lower(edges_[chunk.owned[k]].vertex[1], chunk.ends[k]);
    commit(chunk.kept[k], chunk.pairs);
  }
}

void SelfContactProximity::examine_edges(int e, const Eigen::AlignedBox3d& e_box, int f,
                                         const Eigen::AlignedBox3d& f_box, double& own0,
                                         double& own1, Kept& kept) {
  const Feature &edge = edges_[e], &other = edges_[f];
  const int p0 = edge.vertex[0], p1 = edge.vertex[1], q0 = other.vertex[0], q1 = other.vertex[1];
  if (q0 == p0 || q0 == p1 || q1 == p0 || q1 == p1) return;
  const Eigen::Array3d gap = box_gap(e_box, f_box);
  const bool found =
      (gap <= static_cast<double>(edge.reach) + static_cast<double>(other.reach)).all();
  const double low2 = gap.matrix().squaredNorm();  // the distance is no less than its root
  const double c2 = contact_distance_ * contact_distance_;
  const double limit = std::max(std::max(own0, own1), std::max(nearest(q0), nearest(q1)));
  const bool for_bounds = found && low2 < limit * limit;
  // Whether a pair in the rest shape too, asked only where it decides something.
  const auto at_rest = [&] { return rest_->edge_edge(*surface_, e, f); };
  const bool may_pair = low2 < c2 && (for_bounds || !at_rest());
  if (!for_bounds && !may_pair) return;
  const Eigen::Vector3d &x0 = points_[p0], &x1 = points_[p1], &y0 = points_[q0], &y1 = points_[q1];
  const Eigen::Vector2d su = closest_on_segments(x0, x1, y0, y1);
  const Eigen::Vector3d q = (1.0 - su(0)) * x0 + su(0) * x1 - (1.0 - su(1)) * y0 - su(1) * y1;
  const double distance = q.norm();
  if (for_bounds) {
    own0 = std::min(own0, distance);
    own1 = std::min(own1, distance);
    lower(q0, distance);
    lower(q1, distance);
  }
  if (may_pair && distance * distance < c2 && !(for_bounds && at_rest())) {
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
  // In the order of the other feature's vertices, the same on every thread count: whatever
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

}  // namespace wobble

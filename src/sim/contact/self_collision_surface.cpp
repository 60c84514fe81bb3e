#include "sim/contact/self_collision_surface.h"

#include <algorithm>
#include <unordered_map>
#include <utility>

#include "sim/contact/closest_points.h"
#include "sim/contact/vertex_row.h"

namespace wobble {

namespace {

// (owner, id) pairs into compressed rows, ids sorted within each owner.
void compress(std::vector<std::pair<int, int>>& pairs, int owners, CompressedRows& rows) {
  std::sort(pairs.begin(), pairs.end());
  rows.start.assign(owners + 1, 0);
  rows.ids.resize(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    ++rows.start[pairs[k].first + 1];
    rows.ids[k] = pairs[k].second;
  }
  for (int o = 0; o < owners; ++o)
    rows.start[o + 1] += rows.start[o];
}

}  // namespace

bool CompressedRows::contains(int owner, int id) const {
  return std::binary_search(ids.begin() + start[owner], ids.begin() + start[owner + 1], id);
}

void keep_nearest(std::vector<std::pair<double, int>>& candidates, int count,
                  std::vector<int>& ids) {
  if (static_cast<int>(candidates.size()) > count) {
    std::nth_element(candidates.begin(), candidates.begin() + count, candidates.end());
    candidates.resize(count);
  }
  const std::size_t first = ids.size();
  for (const auto& candidate : candidates)
    ids.push_back(candidate.second);
  std::sort(ids.begin() + static_cast<std::ptrdiff_t>(first), ids.end());
}

SelfCollisionSurface::SelfCollisionSurface(const SpringNetwork& network)
    : rest(network.V), triangles(network.F) {
  const int n = static_cast<int>(rest.rows());
  std::vector<char> on_surface(n, 0);
  std::unordered_map<long long, int> edge_ids;
  std::vector<std::pair<int, int>> edge_list;
  double edge_sum = 0.0;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    for (int c = 0; c < 3; ++c) {
      const int i = triangles(t, c), j = triangles(t, (c + 1) % 3);
      on_surface[i] = 1;
      const int low = std::min(i, j), high = std::max(i, j);
      const long long key = static_cast<long long>(low) * n + high;
      if (edge_ids.emplace(key, static_cast<int>(edge_list.size())).second) {
        edge_list.emplace_back(low, high);
        edge_sum += (vertex_row(rest, i) - vertex_row(rest, j)).norm();
      }
    }
  }
  edges.resize(static_cast<Eigen::Index>(edge_list.size()), 2);
  for (std::size_t e = 0; e < edge_list.size(); ++e) {
    edges(e, 0) = edge_list[e].first;
    edges(e, 1) = edge_list[e].second;
  }
  for (int i = 0; i < n; ++i) {
    if (on_surface[i]) vertices.push_back(i);
  }
  mean_edge = edge_list.empty() ? 0.0 : edge_sum / static_cast<double>(edge_list.size());
  if (n > 0) size = (rest.colwise().maxCoeff() - rest.colwise().minCoeff()).norm();
  std::vector<std::pair<int, int>> incident;
  for (Eigen::Index e = 0; e < edges.rows(); ++e) {
    incident.emplace_back(edges(e, 0), static_cast<int>(e));
    incident.emplace_back(edges(e, 1), static_cast<int>(e));
  }
  compress(incident, n, vertex_edges);
  incident.clear();
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    for (int c = 0; c < 3; ++c)
      incident.emplace_back(triangles(t, c), static_cast<int>(t));
  }
  compress(incident, n, vertex_triangles);
}

void RestNeighbours::find(const SelfCollisionSurface& surface, double reach) {
  const Eigen::MatrixXd& V = surface.rest;
  const int n = static_cast<int>(V.rows());
  // Rest boxes grown by half the reach: features within it have overlapping boxes.
  const auto grown = [&](std::initializer_list<int> vertices) {
    Eigen::AlignedBox3d box;
    for (const int i : vertices)
      box.extend(vertex_row(V, i));
    box.min().array() -= 0.5 * reach;
    box.max().array() += 0.5 * reach;
    return box;
  };
  const double cell = std::max(surface.mean_edge, reach);
  std::vector<std::pair<double, int>> near;
  std::vector<Eigen::AlignedBox3d> boxes;
  SpatialGrid grid;

  boxes.resize(surface.triangles.rows());
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t)
    boxes[t] = grown({surface.triangles(t, 0), surface.triangles(t, 1), surface.triangles(t, 2)});
  grid.build(boxes, cell);
  triangles_.start.assign(n + 1, 0);
  triangles_.ids.clear();
  for (int v = 0; v < n; ++v) {
    near.clear();
    if (surface.vertex_triangles.begin(v) != surface.vertex_triangles.end(v)) {
      const Eigen::Vector3d p = vertex_row(V, v);
      int examined = 0;
      grid.for_each_overlapping(grown({v}), boxes, [&](int t) {
        const int a = surface.triangles(t, 0), b = surface.triangles(t, 1),
                  c = surface.triangles(t, 2);
        if (++examined > max_examined) return false;  // every box met counts, kept or not
        if (v == a || v == b || v == c) return true;
        const Eigen::Vector3d alpha =
            closest_on_triangle(p, vertex_row(V, a), vertex_row(V, b), vertex_row(V, c));
        const double distance = (p - alpha(0) * vertex_row(V, a) - alpha(1) * vertex_row(V, b) -
                                 alpha(2) * vertex_row(V, c))
                                    .norm();
        if (distance < reach) near.emplace_back(distance, t);
        return true;
      });
    }
    keep_nearest(near, max_per_owner, triangles_.ids);
    triangles_.start[v + 1] = static_cast<int>(triangles_.ids.size());
  }

  const int edge_count = static_cast<int>(surface.edges.rows());
  boxes.resize(edge_count);
  for (int e = 0; e < edge_count; ++e)
    boxes[e] = grown({surface.edges(e, 0), surface.edges(e, 1)});
  grid.build(boxes, cell);
  edges_.start.assign(edge_count + 1, 0);
  edges_.ids.clear();
  for (int e = 0; e < edge_count; ++e) {
    near.clear();
    const int p0 = surface.edges(e, 0), p1 = surface.edges(e, 1);
    int examined = 0;
    grid.for_each_overlapping(boxes[e], boxes, [&](int f) {
      if (++examined > max_examined) return false;  // every box met counts, kept or not
      if (f <= e) return true;
      const int q0 = surface.edges(f, 0), q1 = surface.edges(f, 1);
      if (q0 == p0 || q0 == p1 || q1 == p0 || q1 == p1) return true;
      const Eigen::Vector2d su = closest_on_segments(vertex_row(V, p0), vertex_row(V, p1),
                                                     vertex_row(V, q0), vertex_row(V, q1));
      const double distance = ((1.0 - su(0)) * vertex_row(V, p0) + su(0) * vertex_row(V, p1) -
                               (1.0 - su(1)) * vertex_row(V, q0) - su(1) * vertex_row(V, q1))
                                  .norm();
      if (distance < reach) near.emplace_back(distance, f);
      return true;
    });
    keep_nearest(near, max_per_owner, edges_.ids);
    edges_.start[e + 1] = static_cast<int>(edges_.ids.size());
  }
}

std::size_t RestNeighbours::memory_bytes() const {
  return triangles_.memory_bytes() + edges_.memory_bytes();
}

}  // namespace wobble

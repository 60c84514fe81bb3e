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

RestNeighbours::RestNeighbours(const SelfCollisionSurface& surface, double reach)
    : reach_(reach > 0.0 ? reach : 0.0) {
  if (reach_ > 0.0) pack_rows(surface.rest, rest_);
}

bool RestNeighbours::vertex_triangle(const SelfCollisionSurface& surface, int vertex,
                                     int triangle) const {
  if (!(reach_ > 0.0)) return false;
  const Eigen::Vector3d& p = rest_[vertex];
  const Eigen::Vector3d &a = rest_[surface.triangles(triangle, 0)],
                        &b = rest_[surface.triangles(triangle, 1)],
                        &c = rest_[surface.triangles(triangle, 2)];
  // No nearer than the gap between the point and the triangle's box.
  const Eigen::Array3d low = a.array().min(b.array()).min(c.array()),
                       high = a.array().max(b.array()).max(c.array());
  const double reach2 = reach_ * reach_;
  if ((p.array() - high).max(low - p.array()).max(0.0).matrix().squaredNorm() >= reach2)
    return false;
  // No farther than its nearest corner (most neighbours: the answer without the closest point).
  if ((p - a).squaredNorm() < reach2 || (p - b).squaredNorm() < reach2 ||
      (p - c).squaredNorm() < reach2) {
    return true;
  }
  const Eigen::Vector3d alpha = closest_on_triangle(p, a, b, c);
  return (p - alpha(0) * a - alpha(1) * b - alpha(2) * c).norm() < reach_;
}

bool RestNeighbours::edge_edge(const SelfCollisionSurface& surface, int e, int f) const {
  if (!(reach_ > 0.0)) return false;
  const Eigen::Vector3d &p0 = rest_[surface.edges(e, 0)], &p1 = rest_[surface.edges(e, 1)],
                        &q0 = rest_[surface.edges(f, 0)], &q1 = rest_[surface.edges(f, 1)];
  const Eigen::Array3d gap = (p0.array().min(p1.array()) - q0.array().max(q1.array()))
                                 .max(q0.array().min(q1.array()) - p0.array().max(p1.array()))
                                 .max(0.0);
  const double reach2 = reach_ * reach_;
  if (gap.matrix().squaredNorm() >= reach2) return false;
  // No farther than its nearest two ends.
  if ((p0 - q0).squaredNorm() < reach2 || (p0 - q1).squaredNorm() < reach2 ||
      (p1 - q0).squaredNorm() < reach2 || (p1 - q1).squaredNorm() < reach2) {
    return true;
  }
  const Eigen::Vector2d su = closest_on_segments(p0, p1, q0, q1);
  return ((1.0 - su(0)) * p0 + su(0) * p1 - (1.0 - su(1)) * q0 - su(1) * q1).norm() < reach_;
}

}  // namespace wobble

#include "tet_mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace wobble {

namespace {

// Positive when (b − a, c − a, d − a) is right-handed.
double signed_volume(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                     const Eigen::Vector3d& d) {
  return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

}  // namespace

double tet_signed_volume(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T, Eigen::Index t) {
  return signed_volume(V.row(T(t, 0)).transpose(), V.row(T(t, 1)).transpose(),
                       V.row(T(t, 2)).transpose(), V.row(T(t, 3)).transpose());
}

Eigen::MatrixXi tet_mesh_edges(const Eigen::MatrixXi& T) {
  std::vector<std::pair<int, int>> edges;
  edges.reserve(6 * T.rows());
  for (Eigen::Index t = 0; t < T.rows(); ++t) {
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b) {
        edges.emplace_back(std::min(T(t, a), T(t, b)), std::max(T(t, a), T(t, b)));
      }
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  Eigen::MatrixXi E(edges.size(), 2);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    E(e, 0) = edges[e].first;
    E(e, 1) = edges[e].second;
  }
  return E;
}

Eigen::MatrixXi tet_mesh_boundary_faces(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T) {
  // For a positively oriented tetrahedron (a, b, c, d) these four faces have outward normals.
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  // Key: the sorted corners; value: the oriented face and how many tetrahedra share it.
  std::map<std::array<int, 3>, std::pair<std::array<int, 3>, int>> faces;
  for (Eigen::Index t = 0; t < T.rows(); ++t) {
    std::array<int, 4> corners = {T(t, 0), T(t, 1), T(t, 2), T(t, 3)};
    if (tet_signed_volume(V, T, t) < 0.0) std::swap(corners[2], corners[3]);
    for (const auto& face : kFaces) {
      const std::array<int, 3> oriented = {corners[face[0]], corners[face[1]], corners[face[2]]};
      std::array<int, 3> key = oriented;
      std::sort(key.begin(), key.end());
      auto [it, inserted] = faces.try_emplace(key, oriented, 0);
      ++it->second.second;
    }
  }
  std::vector<std::array<int, 3>> boundary;
  for (const auto& [key, value] : faces) {
    if (value.second == 1) boundary.push_back(value.first);
  }
  Eigen::MatrixXi F(boundary.size(), 3);
  for (std::size_t f = 0; f < boundary.size(); ++f) {
    F.row(f) << boundary[f][0], boundary[f][1], boundary[f][2];
  }
  return F;
}

Eigen::VectorXd tet_mesh_lumped_masses(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T,
                                       double density) {
  Eigen::VectorXd m = Eigen::VectorXd::Zero(V.rows());
  for (Eigen::Index t = 0; t < T.rows(); ++t) {
    const double quarter = density * std::abs(tet_signed_volume(V, T, t)) / 4.0;
    for (int c = 0; c < 4; ++c)
      m(T(t, c)) += quarter;
  }
  return m;
}

bool tetrahedron_is_flat(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c, const Eigen::Vector3d& d) {
  double longest = 0.0;
  for (const Eigen::Vector3d& edge :
       {Eigen::Vector3d(b - a), Eigen::Vector3d(c - a), Eigen::Vector3d(d - a),
        Eigen::Vector3d(c - b), Eigen::Vector3d(d - b), Eigen::Vector3d(d - c)}) {
    longest = std::max(longest, edge.norm());
  }
  return !(std::abs(signed_volume(a, b, c, d)) > 1e-12 * longest * longest * longest);
}

}  // namespace wobble

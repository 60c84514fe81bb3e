#ifndef WOBBLE_TESTS_SIM_SELF_CONTACT_PROXIMITY_MESHES_H
#define WOBBLE_TESTS_SIM_SELF_CONTACT_PROXIMITY_MESHES_H

// Small meshes, brute-force distances and a find() at one place, for the tests of
// sim/contact/self_contact_proximity.h.

#include <Eigen/Core>
#include <algorithm>
#include <random>
#include <vector>

#include "sim/contact/closest_points.h"
#include "sim/contact/self_contact_proximity.h"
#include "sim/contact/vertex_row.h"

namespace wobble::testing {

struct Mesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;
  // An n×n grid of spacing h in a plane z = const, from `origin`, two triangles a cell.
  void add_grid(int n, double h, const Eigen::Vector3d& origin) {
    const int first = static_cast<int>(vertices.size());
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j)
        vertices.push_back(origin + Eigen::Vector3d(j * h, i * h, 0.0));
    }
    for (int i = 0; i + 1 < n; ++i) {
      for (int j = 0; j + 1 < n; ++j) {
        const int a = first + i * n + j;
        triangles.emplace_back(a, a + 1, a + n + 1);
        triangles.emplace_back(a, a + n + 1, a + n);
      }
    }
  }
  void add_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    const int first = static_cast<int>(vertices.size());
    vertices.insert(vertices.end(), {a, b, c});
    triangles.emplace_back(first, first + 1, first + 2);
  }
  Eigen::MatrixXd x() const {
    Eigen::MatrixXd V(vertices.size(), 3);
    for (std::size_t i = 0; i < vertices.size(); ++i)
      V.row(i) = vertices[i].transpose();
    return V;
  }
  wobble::SpringNetwork network() const {
    wobble::SpringNetwork network;
    network.V = x();
    network.F.resize(triangles.size(), 3);
    for (std::size_t t = 0; t < triangles.size(); ++t)
      network.F.row(t) = triangles[t].transpose();
    network.m = Eigen::VectorXd::Ones(network.V.rows());
    return network;
  }
};

// A mesh's surface, its rest neighbours within `rest_reach` of its own positions (0: none), and
// find()'s answer at those positions.
struct Found {
  wobble::SelfCollisionSurface surface;
  wobble::RestNeighbours rest;
  Eigen::MatrixXd x;
  std::vector<SelfContactPair> pairs;
  Eigen::VectorXd bounds;
  double floor = 0.0;   // the find's floor f (m)
  bool covers = false;  // covers_every_pair()
  Found(const Mesh& mesh, const Eigen::VectorXd& reach, double contact_distance,
        double rest_reach = 0.0, wobble::WorkerPool* pool = nullptr)
      : surface(mesh.network()), x(mesh.x()) {
    rest = wobble::RestNeighbours(surface, rest_reach);
    SelfContactProximity proximity(pool);
    proximity.find(surface, rest, x, reach, contact_distance, pairs, bounds);
    floor = proximity.floor();
    covers = proximity.covers_every_pair();
  }
  // The bound the formula gives a vertex whose min(R, ½d) is `half` (m): γ·max(0, half − ½f).
  double bound(double half) const {
    return SelfContactProximity::bound_fraction * std::max(0.0, half - 0.5 * floor);
  }
};

inline Eigen::VectorXd constant_reach(const Mesh& mesh, double r) {
  return Eigen::VectorXd::Constant(mesh.vertices.size(), r);
}

inline double vertex_triangle_distance(const Eigen::MatrixXd& x, int v, const Eigen::Vector3i& t) {
  const Eigen::Vector3d p = vertex_row(x, v), a = vertex_row(x, t(0)), b = vertex_row(x, t(1)),
                        c = vertex_row(x, t(2));
  const Eigen::Vector3d alpha = wobble::closest_on_triangle(p, a, b, c);
  return (p - alpha(0) * a - alpha(1) * b - alpha(2) * c).norm();
}

inline double edge_edge_distance(const Eigen::MatrixXd& x, int p0, int p1, int q0, int q1) {
  const Eigen::Vector3d x0 = vertex_row(x, p0), x1 = vertex_row(x, p1), y0 = vertex_row(x, q0),
                        y1 = vertex_row(x, q1);
  const Eigen::Vector2d su = wobble::closest_on_segments(x0, x1, y0, y1);
  return ((1.0 - su(0)) * x0 + su(0) * x1 - (1.0 - su(1)) * y0 - su(1) * y1).norm();
}

inline bool share_vertex(const SelfContactPair& pair) {
  const int first = pair.vertex_triangle ? 1 : 2;
  for (int i = 0; i < first; ++i) {
    for (int j = first; j < 4; ++j) {
      if (pair.vertex[i] == pair.vertex[j]) return true;
    }
  }
  return false;
}

// A probe triangle whose corner `tip` points down at the rest, its other corners far above.
inline void add_probe(Mesh& mesh, const Eigen::Vector3d& tip) {
  mesh.add_triangle(tip, tip + Eigen::Vector3d(0.1, 0.0, 0.5),
                    tip + Eigen::Vector3d(0.0, 0.1, 0.5));
}

// An accordion of rows × rows vertices: panels 2 mm apart, each 4 cm tall, jittered.
inline Mesh accordion(int rows, unsigned seed) {
  Mesh mesh;
  mesh.add_grid(rows, 0.01, Eigen::Vector3d::Zero());
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-0.0005, 0.0005);
  for (int v = 0; v < static_cast<int>(mesh.vertices.size()); ++v) {
    const int i = v / rows, j = v % rows;
    mesh.vertices[v] = Eigen::Vector3d(0.002 * j + jitter(random), 0.01 * i + jitter(random),
                                       (j % 2 ? 0.02 : -0.02) + jitter(random));
  }
  return mesh;
}

inline bool same(const std::vector<SelfContactPair>& a, const std::vector<SelfContactPair>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a[k].vertex_triangle != b[k].vertex_triangle || a[k].depth != b[k].depth ||
        a[k].normal != b[k].normal)
      return false;
    for (int i = 0; i < 4; ++i) {
      if (a[k].vertex[i] != b[k].vertex[i] || a[k].beta[i] != b[k].beta[i]) return false;
    }
  }
  return true;
}

}  // namespace wobble::testing

#endif

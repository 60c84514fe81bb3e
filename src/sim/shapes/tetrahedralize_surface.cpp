#include "tetrahedralize_surface.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include "sim/input_error.h"
#include "tet_mesh.h"

namespace wobble {

namespace {

void check_closed_surface(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  if (V.cols() != 3) throw InputError("surface vertices must have 3 columns");
  if (F.cols() != 3) throw InputError("surface triangles must have 3 columns");
  if (F.rows() == 0) throw InputError("the surface has no triangles");
  if (!V.allFinite()) throw InputError("a surface vertex position is not finite");
  // (smaller index, larger index, 1 if stepped from smaller to larger): sorted, each undirected
  // edge of a closed, consistently oriented surface appears exactly twice, once per direction.
  std::vector<std::tuple<int, int, int>> edges;
  edges.reserve(3 * F.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const int a = F(f, c), b = F(f, (c + 1) % 3);
      if (a < 0 || a >= V.rows()) {
        throw InputError("surface triangle " + std::to_string(f) + " refers to vertex " +
                         std::to_string(a) + "; expected 0 to " + std::to_string(V.rows() - 1));
      }
      if (a == b) throw InputError("surface triangle " + std::to_string(f) + " repeats a vertex");
      edges.emplace_back(std::min(a, b), std::max(a, b), a < b ? 1 : 0);
    }
  }
  std::sort(edges.begin(), edges.end());
  long open = 0, crowded = 0, misoriented = 0;
  for (std::size_t e = 0; e < edges.size();) {
    std::size_t end = e, forward = 0;
    while (end < edges.size() && std::get<0>(edges[end]) == std::get<0>(edges[e]) &&
           std::get<1>(edges[end]) == std::get<1>(edges[e]))
      forward += std::get<2>(edges[end++]);
    const std::size_t uses = end - e;
    if (uses == 1) ++open;
    if (uses > 2) ++crowded;
    if (uses == 2 && forward != 1) ++misoriented;
    e = end;
  }
  if (open > 0) {
    throw InputError("the surface is not closed: " + std::to_string(open) +
                     " edges belong to one triangle only");
  }
  if (crowded > 0) {
    throw InputError("the surface is not manifold: " + std::to_string(crowded) +
                     " edges belong to more than two triangles");
  }
  if (misoriented > 0) {
    throw InputError("the surface is not consistently oriented: " + std::to_string(misoriented) +
                     " edges are walked the same way by both their triangles");
  }
}

// Σ Ω / 4π with the solid angle Ω of each triangle seen from p (Van Oosterom and Strackee:
// tan(Ω/2) = a·(b×c) / (|a||b||c| + (a·b)|c| + (b·c)|a| + (c·a)|b|), a, b, c the corners
// relative to p). atan2 keeps the right branch when the denominator is negative.
double winding_number(const Eigen::Matrix3Xd& corners, const Eigen::Vector3d& p) {
  double total = 0.0;
  for (Eigen::Index f = 0; f < corners.cols(); f += 3) {
    const Eigen::Vector3d a = corners.col(f) - p, b = corners.col(f + 1) - p,
                          c = corners.col(f + 2) - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    total += 2.0 * std::atan2(numerator, denominator);
  }
  constexpr double kPi = 3.14159265358979323846;
  return total / (4.0 * kPi);
}

// The point of triangle abc closest to p, found by which Voronoi region (corner, edge or face)
// of the triangle p projects into (Ericson, Real-Time Collision Detection, §5.1.5).
Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                          const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double sum = va + vb + vc;
  // Only a zero-area triangle gets here with sum 0; the triangles sharing its edges then give
  // the true closest point, so any point of it will do.
  if (!(sum > 0.0)) return a;
  return a + ab * (vb / sum) + ac * (vc / sum);
}

// Move each boundary vertex of the tetrahedral mesh (TV, TT) towards its closest point on the
// surface, as far as keeps every tetrahedron at min_volume or more. `corners` holds the
// surface's triangles as consecutive column triples.
void snap_boundary_to_surface(const Eigen::Matrix3Xd& corners, double min_volume,
                              const Eigen::MatrixXi& TT, Eigen::MatrixXd& TV) {
  // Tetrahedra touching each vertex, as compressed rows.
  const int used = static_cast<int>(TV.rows());
  std::vector<int> first(used + 1, 0), incident(4 * TT.rows());
  for (Eigen::Index t = 0; t < TT.rows(); ++t) {
    for (int c = 0; c < 4; ++c)
      ++first[TT(t, c) + 1];
  }
  for (int v = 0; v < used; ++v)
    first[v + 1] += first[v];
  std::vector<int> fill(first.begin(), first.end() - 1);
  for (Eigen::Index t = 0; t < TT.rows(); ++t) {
    for (int c = 0; c < 4; ++c)
      incident[fill[TT(t, c)]++] = static_cast<int>(t);
  }
  // Volume is linear in any one corner's position, so on the way from a vertex's position to
  // its target each incident volume is linear in the share travelled, and the farthest share
  // that keeps them all at min_volume or more follows exactly. The 1e-9 absorbs rounding.
  min_volume *= 1.0 + 1e-9;
  const auto farthest_share = [&](int v, const Eigen::RowVector3d& target) {
    const Eigen::RowVector3d start = TV.row(v);
    double share = 1.0;
    for (int n = first[v]; n < first[v + 1]; ++n) {
      const double before = tet_signed_volume(TV, TT, incident[n]);
      TV.row(v) = target;
      const double after = tet_signed_volume(TV, TT, incident[n]);
      TV.row(v) = start;
      if (after < min_volume) share = std::min(share, (before - min_volume) / (before - after));
    }
    return std::max(share, 0.0);
  };

  struct Snap {
    int vertex;
    Eigen::RowVector3d target;  // closest point on the surface
    double distance;
  };
  std::vector<Snap> pending;
  {
    const Eigen::MatrixXi boundary = tet_mesh_boundary_faces(TV, TT);
    std::vector<bool> on_boundary(used, false);
    for (Eigen::Index i = 0; i < boundary.size(); ++i)
      on_boundary[boundary(i)] = true;
    for (int v = 0; v < used; ++v) {
      if (!on_boundary[v]) continue;
      const Eigen::Vector3d p = TV.row(v).transpose();
      Snap snap{v, TV.row(v), std::numeric_limits<double>::infinity()};
      for (Eigen::Index f = 0; f < corners.cols(); f += 3) {
        const Eigen::Vector3d q =
            closest_point_on_triangle(p, corners.col(f), corners.col(f + 1), corners.col(f + 2));
        const double distance = (q - p).norm();
        if (distance < snap.distance) snap = {v, q.transpose(), distance};
      }
      pending.push_back(snap);
    }
  }
  // Nearest first: a vertex close to the surface needs little room, while the far ones, the
  // outer corners of the staircase, are the ones that would flatten a tetrahedron. On the test
  // sphere (resolution 12) index order left 153 of 674 vertices short, nearest first 96.
  std::stable_sort(pending.begin(), pending.end(),
                   [](const Snap& a, const Snap& b) { return a.distance < b.distance; });
  // A vertex stopped short may go farther once its neighbours have moved.
  for (int pass = 0; pass < 3 && !pending.empty(); ++pass) {
    std::size_t kept = 0;
    for (std::size_t b = 0; b < pending.size(); ++b) {
      const Snap snap = pending[b];
      const Eigen::RowVector3d start = TV.row(snap.vertex);
      const double share = farthest_share(snap.vertex, snap.target);
      TV.row(snap.vertex) = share == 1.0 ? snap.target : start + share * (snap.target - start);
      if (share < 1.0) pending[kept++] = snap;
    }
    pending.resize(kept);
  }
}

// The grid of step 1: cells of side h along each axis (h = 0 for a surface of zero size).
std::array<int, 3> grid_cells(const Eigen::MatrixXd& V, int resolution, double& h) {
  const Eigen::Vector3d lo = V.colwise().minCoeff(), hi = V.colwise().maxCoeff();
  h = (hi - lo).maxCoeff() / resolution;
  std::array<int, 3> cells{1, 1, 1};
  if (!(h > 0.0)) return cells;
  for (int a = 0; a < 3; ++a) {
    // The 1e-9 keeps the longest side at exactly `resolution` cells despite rounding.
    cells[a] = std::max(1, static_cast<int>(std::ceil((hi(a) - lo(a)) / h - 1e-9)));
  }
  return cells;
}

}  // namespace

double tetrahedralize_surface_pairs(const Eigen::MatrixXd& V, Eigen::Index triangles,
                                    int resolution) {
  if (V.rows() == 0 || resolution < 1) return 0.0;
  double h = 0.0;
  const std::array<int, 3> cells = grid_cells(V, resolution, h);
  return double(cells[0]) * cells[1] * cells[2] * double(triangles);
}

void tetrahedralize_surface(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, int resolution,
                            Eigen::MatrixXd& TV, Eigen::MatrixXi& TT) {
  if (resolution < 1 || resolution > 1000) {
    throw InputError("tetrahedralization resolution must be 1 to 1000, got " +
                     std::to_string(resolution));
  }
  check_closed_surface(V, F);

  const Eigen::Vector3d lo = V.colwise().minCoeff(), hi = V.colwise().maxCoeff();
  double h = 0.0;
  const std::array<int, 3> cells = grid_cells(V, resolution, h);
  if (!(h > 0.0)) throw InputError("the surface has zero size");
  Eigen::Vector3d origin;
  for (int a = 0; a < 3; ++a)
    origin(a) = 0.5 * (lo(a) + hi(a)) - 0.5 * cells[a] * h;
  const int nx = cells[0] + 1, ny = cells[1] + 1;
  const auto grid_index = [&](const std::array<int, 3>& v) {
    return (v[2] * ny + v[1]) * nx + v[0];
  };

  // Triangle corners gathered column by column, so the inner loop reads memory in order.
  Eigen::Matrix3Xd corners(3, 3 * F.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    for (int c = 0; c < 3; ++c)
      corners.col(3 * f + c) = V.row(F(f, c)).transpose();
  }

  std::vector<std::array<int, 4>> tets;
  std::array<int, 3> axes;
  for (int k = 0; k < cells[2]; ++k) {
    for (int j = 0; j < cells[1]; ++j) {
      for (int i = 0; i < cells[0]; ++i) {
        const Eigen::Vector3d centre = origin + h * Eigen::Vector3d(i + 0.5, j + 0.5, k + 0.5);
        if (!(std::abs(winding_number(corners, centre)) > 0.5)) continue;
        axes = {0, 1, 2};
        do {
          // The walk from corner (i,j,k) to (i+1,j+1,k+1) stepping the axes in this order; its
          // orientation is the permutation's sign, so odd ones get two corners swapped.
          std::array<int, 3> corner = {i, j, k};
          std::array<int, 4> tet;
          tet[0] = grid_index(corner);
          for (int step = 0; step < 3; ++step) {
            ++corner[axes[step]];
            tet[step + 1] = grid_index(corner);
          }
          const int inversions = (axes[0] > axes[1]) + (axes[0] > axes[2]) + (axes[1] > axes[2]);
          if (inversions % 2 == 1) std::swap(tet[2], tet[3]);
          tets.push_back(tet);
        } while (std::next_permutation(axes.begin(), axes.end()));
      }
    }
  }
  if (tets.empty()) {
    throw InputError("no cell centre is inside the surface at resolution " +
                     std::to_string(resolution) + "; expected a surface enclosing some volume");
  }

  // Keep only the grid vertices that a tetrahedron uses, in grid order.
  std::vector<int> new_index(static_cast<std::size_t>(nx) * ny * (cells[2] + 1), -1);
  for (const auto& tet : tets) {
    for (int v : tet)
      new_index[v] = 0;
  }
  int used = 0;
  for (int& index : new_index) {
    if (index == 0) index = used++;
  }
  TV.resize(used, 3);
  for (std::size_t g = 0; g < new_index.size(); ++g) {
    if (new_index[g] < 0) continue;
    const int i = static_cast<int>(g % nx), j = static_cast<int>(g / nx % ny),
              k = static_cast<int>(g / nx / ny);
    TV.row(new_index[g]) = (origin + h * Eigen::Vector3d(i, j, k)).transpose();
  }
  TT.resize(tets.size(), 4);
  for (std::size_t t = 0; t < tets.size(); ++t) {
    for (int c = 0; c < 4; ++c)
      TT(t, c) = new_index[tets[t][c]];
  }

  snap_boundary_to_surface(corners, 0.1 * h * h * h / 6.0, TT, TV);
}

}  // namespace wobble

#include "mesh_crossings.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace wobble::testing {

namespace {

// o(a,b,c,d) = (b−a)·((c−a)×(d−a)) over four vertices, always evaluated with the vertices
// sorted by index and the sign of the permutation applied, so the same four vertices give the
// same number whichever test asks (a segment through the shared edge of two triangles is judged
// the same way by both).
double orientation(const Eigen::MatrixXd& V, std::array<int, 4> ids) {
  double sign = 1.0;
  for (int i = 1; i < 4; ++i) {
    for (int j = i; j > 0 && ids[j - 1] > ids[j]; --j) {
      std::swap(ids[j - 1], ids[j]);
      sign = -sign;
    }
  }
  const Eigen::Vector3d a = V.row(ids[0]).transpose();
  const Eigen::Vector3d ab = V.row(ids[1]).transpose() - a;
  const Eigen::Vector3d ac = V.row(ids[2]).transpose() - a;
  const Eigen::Vector3d ad = V.row(ids[3]).transpose() - a;
  return sign * ab.dot(ac.cross(ad));
}

// The segment p–q against the closed triangle a,b,c (no shared vertex): p and q more than `gap`
// from the triangle's plane on opposite sides, and the line through them meeting the triangle.
bool segment_crosses_triangle(const Eigen::MatrixXd& V, int p, int q, int a, int b, int c,
                              double gap) {
  const Eigen::Vector3d va = V.row(a).transpose();
  const double twice_area = (Eigen::Vector3d(V.row(b).transpose()) - va)
                                .cross(Eigen::Vector3d(V.row(c).transpose()) - va)
                                .norm();
  if (!(twice_area > 0.0)) return false;  // degenerate triangle: no plane to cross
  // o(a,b,c,x) = 2·area × the signed distance of x from the plane.
  const double dp = orientation(V, {a, b, c, p}) / twice_area;
  const double dq = orientation(V, {a, b, c, q}) / twice_area;
  if (!((dp > gap && dq < -gap) || (dp < -gap && dq > gap))) return false;
  // The line p–q meets the closed triangle iff it passes on the same side of all three edges
  // (a zero: through an edge or a vertex, which counts).
  const double ab = orientation(V, {p, q, a, b});
  const double bc = orientation(V, {p, q, b, c});
  const double ca = orientation(V, {p, q, c, a});
  const bool any_positive = ab > 0.0 || bc > 0.0 || ca > 0.0;
  const bool any_negative = ab < 0.0 || bc < 0.0 || ca < 0.0;
  return !(any_positive && any_negative);
}

// An endpoint closer than this to a triangle's plane, as a fraction of the mesh's bounding box
// diagonal, is on the plane: far above rounding (a flat sheet turned in space, or solved by the
// simulator, scatters by about 1e-16 of its size) and far below any thickness cloth keeps.
constexpr double plane_gap = 1e-9;

constexpr int cell_bits = 21;
constexpr std::int64_t max_cell = (std::int64_t{1} << cell_bits) - 1;
// A triangle whose box covers more cells than this is tested against every edge instead.
constexpr std::int64_t max_cells_per_triangle = 512;

struct CellRange {
  std::array<std::int64_t, 3> low, high;
  std::int64_t count() const {
    return (high[0] - low[0] + 1) * (high[1] - low[1] + 1) * (high[2] - low[2] + 1);
  }
};

std::uint64_t cell_key(std::int64_t x, std::int64_t y, std::int64_t z) {
  return (static_cast<std::uint64_t>(x) << (2 * cell_bits)) |
         (static_cast<std::uint64_t>(y) << cell_bits) | static_cast<std::uint64_t>(z);
}

}  // namespace

long count_mesh_crossings(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                          std::vector<std::pair<int, int>>* crossings, Eigen::MatrixXi* edges) {
  if (crossings) crossings->clear();
  std::vector<std::pair<int, int>> unique_edges;
  unique_edges.reserve(3 * F.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int i = F(f, k), j = F(f, (k + 1) % 3);
      unique_edges.emplace_back(std::min(i, j), std::max(i, j));
    }
  }
  std::sort(unique_edges.begin(), unique_edges.end());
  unique_edges.erase(std::unique(unique_edges.begin(), unique_edges.end()), unique_edges.end());
  if (edges) {
    edges->resize(static_cast<Eigen::Index>(unique_edges.size()), 2);
    for (std::size_t e = 0; e < unique_edges.size(); ++e) {
      (*edges)(static_cast<Eigen::Index>(e), 0) = unique_edges[e].first;
      (*edges)(static_cast<Eigen::Index>(e), 1) = unique_edges[e].second;
    }
  }
  if (F.rows() == 0) return 0;

  // Boxes of the triangles and the grid they live in.
  std::vector<Eigen::AlignedBox3d> boxes(F.rows());
  Eigen::AlignedBox3d all;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    for (int k = 0; k < 3; ++k)
      boxes[f].extend(V.row(F(f, k)).transpose());
    all.extend(boxes[f]);
  }
  double cell = 0.0;
  for (const auto& [i, j] : unique_edges)
    cell += (V.row(i) - V.row(j)).norm();
  cell /= static_cast<double>(unique_edges.size());
  // Keep the cell coordinates within their bits (and away from a zero cell).
  cell = std::max({cell, all.sizes().maxCoeff() / static_cast<double>(max_cell - 1), 1e-300});
  const Eigen::Vector3d origin = all.min();
  const double gap = plane_gap * all.diagonal().norm();
  const auto range = [&](const Eigen::AlignedBox3d& box) {
    CellRange r;
    for (int d = 0; d < 3; ++d) {
      r.low[d] = std::clamp<std::int64_t>(
          static_cast<std::int64_t>(std::floor((box.min()(d) - origin(d)) / cell)), 0, max_cell);
      r.high[d] = std::clamp<std::int64_t>(
          static_cast<std::int64_t>(std::floor((box.max()(d) - origin(d)) / cell)), 0, max_cell);
    }
    return r;
  };

  std::vector<std::pair<std::uint64_t, int>> grid;  // (cell, triangle), sorted by cell
  std::vector<int> large;
  grid.reserve(4 * F.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const CellRange r = range(boxes[f]);
    if (r.count() > max_cells_per_triangle) {
      large.push_back(static_cast<int>(f));
      continue;
    }
    for (std::int64_t x = r.low[0]; x <= r.high[0]; ++x)
      for (std::int64_t y = r.low[1]; y <= r.high[1]; ++y)
        for (std::int64_t z = r.low[2]; z <= r.high[2]; ++z)
          grid.emplace_back(cell_key(x, y, z), static_cast<int>(f));
  }
  std::sort(grid.begin(), grid.end());

  long count = 0;
  std::vector<int> seen(F.rows(), -1);  // the last edge that tested each triangle
  std::vector<int> hits;
  for (std::size_t e = 0; e < unique_edges.size(); ++e) {
    const int p = unique_edges[e].first, q = unique_edges[e].second;
    Eigen::AlignedBox3d segment_box(V.row(p).transpose());
    segment_box.extend(V.row(q).transpose());
    hits.clear();
    const auto test = [&](int f) {
      if (seen[f] == static_cast<int>(e)) return;
      seen[f] = static_cast<int>(e);
      const int a = F(f, 0), b = F(f, 1), c = F(f, 2);
      if (p == a || p == b || p == c || q == a || q == b || q == c) return;
      if (!boxes[f].intersects(segment_box)) return;
      if (segment_crosses_triangle(V, p, q, a, b, c, gap)) hits.push_back(f);
    };
    const CellRange r = range(segment_box);
    // A very long edge would visit more cells than the grid holds entries: test every triangle.
    if (r.count() > static_cast<std::int64_t>(grid.size())) {
      for (Eigen::Index f = 0; f < F.rows(); ++f)
        test(static_cast<int>(f));
    } else {
      for (std::int64_t x = r.low[0]; x <= r.high[0]; ++x) {
        for (std::int64_t y = r.low[1]; y <= r.high[1]; ++y) {
          for (std::int64_t z = r.low[2]; z <= r.high[2]; ++z) {
            const std::uint64_t key = cell_key(x, y, z);
            auto it = std::lower_bound(grid.begin(), grid.end(), std::make_pair(key, -1));
            for (; it != grid.end() && it->first == key; ++it)
              test(it->second);
          }
        }
      }
    }
    for (int f : large)
      test(f);
    count += static_cast<long>(hits.size());
    if (crossings) {
      std::sort(hits.begin(), hits.end());
      for (int f : hits)
        crossings->emplace_back(static_cast<int>(e), f);
    }
  }
  return count;
}

}  // namespace wobble::testing

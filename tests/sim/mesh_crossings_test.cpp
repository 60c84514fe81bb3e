// The test helper that finds a mesh passing through itself, against hand-made meshes and a
// brute-force count.
#include "mesh_crossings.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <chrono>
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

#include "sim/shapes/cloth_grid.h"

namespace {

using wobble::testing::count_mesh_crossings;

wobble::SpringNetwork grid(int resolution, double size = 1.0) {
  wobble::ClothGridOptions options;
  options.resolution = resolution;
  options.size = size;
  return wobble::make_cloth_grid(options);
}

// Every (edge, triangle) pair tested, with a test of its own: where the segment meets the
// triangle's plane, then that point's barycentric coordinates. Same conventions as the helper for
// the cases a random mesh produces (no point lands exactly on a plane).
long brute_force_crossings(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                           const Eigen::MatrixXi& edges) {
  long count = 0;
  for (Eigen::Index e = 0; e < edges.rows(); ++e) {
    const Eigen::Vector3d p = V.row(edges(e, 0)).transpose();
    const Eigen::Vector3d q = V.row(edges(e, 1)).transpose();
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
      bool shared = false;
      for (int k = 0; k < 3; ++k)
        shared = shared || F(f, k) == edges(e, 0) || F(f, k) == edges(e, 1);
      if (shared) continue;
      const Eigen::Vector3d a = V.row(F(f, 0)).transpose();
      const Eigen::Vector3d b = V.row(F(f, 1)).transpose();
      const Eigen::Vector3d c = V.row(F(f, 2)).transpose();
      const Eigen::Vector3d n = (b - a).cross(c - a);
      const double dp = n.dot(p - a), dq = n.dot(q - a);
      if (dp * dq > 0.0 || dp == dq) continue;
      const Eigen::Vector3d x = p + (dp / (dp - dq)) * (q - p);
      const double area = n.squaredNorm();
      const double u = n.dot((c - b).cross(x - b)) / area;
      const double v = n.dot((a - c).cross(x - c)) / area;
      const double w = 1.0 - u - v;
      if (u >= 0.0 && v >= 0.0 && w >= 0.0) ++count;
    }
  }
  return count;
}

TEST(MeshCrossings, TwoPiercingTrianglesReportWhichEdgeCrossesWhichTriangle) {
  Eigen::MatrixXd V(6, 3);
  V << 0, 0, 0,        //
      1, 0, 0,         //
      0, 1, 0,         //
      0.25, 0.25, -1,  // a vertical edge through the first triangle at (0.25, 0.25, 0)
      0.25, 0.25, 1,   //
      3, -1, 0;
  Eigen::MatrixXi F(2, 3);
  F << 0, 1, 2, 3, 4, 5;
  std::vector<std::pair<int, int>> crossings;
  Eigen::MatrixXi edges;
  EXPECT_EQ(count_mesh_crossings(V, F, &crossings, &edges), 2);
  ASSERT_EQ(edges.rows(), 6);
  // Edges in lexicographic order: (0,1) (0,2) (1,2) (3,4) (3,5) (4,5).
  EXPECT_EQ(edges.row(0), Eigen::RowVector2i(0, 1));
  EXPECT_EQ(edges.row(3), Eigen::RowVector2i(3, 4));
  // The second triangle's vertical edge pierces the first triangle, and the first triangle's
  // edge along x (y = 0) passes through the second at x = 0.8.
  const std::vector<std::pair<int, int>> expected = {{0, 1}, {3, 0}};
  EXPECT_EQ(crossings, expected);
}

TEST(MeshCrossings, TouchingDoesNotCountAndPassingThroughDoes) {
  Eigen::MatrixXd V(6, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0,  // triangle in z = 0
      0.25, 0.25, 0,               // a vertex exactly on it
      0.25, 0.25, 1,               //
      3, 3, 3;
  Eigen::MatrixXi F(2, 3);
  F << 0, 1, 2, 3, 4, 5;
  EXPECT_EQ(count_mesh_crossings(V, F), 0);

  // A micrometre through it: both edges that end at that vertex cross.
  V(3, 2) = -1e-6;
  std::vector<std::pair<int, int>> crossings;
  Eigen::MatrixXi edges;
  EXPECT_EQ(count_mesh_crossings(V, F, &crossings, &edges), 2);
  for (const auto& [edge, triangle] : crossings) {
    EXPECT_EQ(edges(edge, 0), 3);
    EXPECT_EQ(triangle, 0);
  }

  // Through the first triangle's edge from (0,0,0) to (1,0,0), exactly: counts, and that edge
  // passes just as exactly through the second triangle's edge (3,4), which counts too.
  V.row(3) << 0.5, 0, -1;
  V.row(4) << 0.5, 0, 1;
  V.row(5) << 3, -3, 0;
  EXPECT_EQ(count_mesh_crossings(V, F, &crossings, &edges), 2);
  const std::vector<std::pair<int, int>> expected = {{0, 1}, {3, 0}};  // (0,1)×1, (3,4)×0
  EXPECT_EQ(crossings, expected);

  // The second triangle laid in the first one's plane, overlapping it: not counted.
  V.row(3) << 0.1, 0.1, 0;
  V.row(4) << 0.6, 0.1, 0;
  V.row(5) << 0.1, 0.6, 0;
  EXPECT_EQ(count_mesh_crossings(V, F), 0);
}

TEST(MeshCrossings, FlatClothHasNoneAndAdjacentPairsAreSkipped) {
  const wobble::SpringNetwork cloth = grid(30);
  EXPECT_EQ(count_mesh_crossings(cloth.V, cloth.F), 0);
  // Tilted out of the y = 0 plane, still flat, still none.
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::MatrixXd turned = cloth.V * turn.transpose();
  EXPECT_EQ(count_mesh_crossings(turned, cloth.F), 0);
}

TEST(MeshCrossings, ParallelStackedSheetsHaveNone) {
  const wobble::SpringNetwork sheet = grid(20);
  const Eigen::Index n = sheet.V.rows();
  Eigen::MatrixXd V(2 * n, 3);
  V << sheet.V, sheet.V;
  V.bottomRows(n).col(1).array() += 0.005;  // a tenth of an edge above
  Eigen::MatrixXi F(2 * sheet.F.rows(), 3);
  F << sheet.F, (sheet.F.array() + static_cast<int>(n)).matrix();
  EXPECT_EQ(count_mesh_crossings(V, F), 0);
}

// A cloth grid folded back over itself at column `fold`, the folded part first rising and then
// sinking through the flat part: y = a·d − b·d² at distance d past the fold line. The folded part
// is also shifted a third of an edge along z and stretched 1.3% along x, so that its vertices
// and edges do not line up exactly with the flat part's (no touching by construction).
Eigen::MatrixXd fold_through(const wobble::SpringNetwork& cloth, int resolution, int fold) {
  const double h = 1.0 / (resolution - 1);
  Eigen::MatrixXd V = cloth.V;
  const double fold_x = -0.5 + fold * h;
  for (int row = 0; row < resolution; ++row) {
    for (int column = fold + 1; column < resolution; ++column) {
      const int i = wobble::cloth_grid_vertex(resolution, row, column);
      const double d = (column - fold) * h;
      V(i, 0) = fold_x - 1.013 * d;
      V(i, 2) += h / 3.0;
      V(i, 1) = 0.5 * d - 2.5 * d * d;  // back through y = 0 at d = 0.2
    }
  }
  return V;
}

TEST(MeshCrossings, AStripFoldedThroughTheRestIsFound) {
  const int n = 20, fold = 12;
  const wobble::SpringNetwork cloth = grid(n);
  const Eigen::MatrixXd V = fold_through(cloth, n, fold);
  std::vector<std::pair<int, int>> crossings;
  Eigen::MatrixXi edges;
  const long count = count_mesh_crossings(V, cloth.F, &crossings, &edges);
  EXPECT_GT(count, n);  // at least one per row of the folded part
  EXPECT_EQ(count, brute_force_crossings(V, cloth.F, edges));
  // Every crossing is a folded edge against an unfolded triangle or the other way round.
  const auto folded = [&](int vertex) { return vertex % n > fold; };
  for (const auto& [edge, triangle] : crossings) {
    const bool edge_folded = folded(edges(edge, 0)) && folded(edges(edge, 1));
    const bool edge_flat = !folded(edges(edge, 0)) && !folded(edges(edge, 1));
    bool triangle_folded = true, triangle_flat = true;
    for (int k = 0; k < 3; ++k) {
      triangle_folded = triangle_folded && folded(cloth.F(triangle, k));
      triangle_flat = triangle_flat && !folded(cloth.F(triangle, k));
    }
    EXPECT_TRUE((edge_folded && triangle_flat) || (edge_flat && triangle_folded))
        << "edge " << edges.row(edge) << ", triangle " << cloth.F.row(triangle);
  }
  // Unfolded, nothing.
  EXPECT_EQ(count_mesh_crossings(cloth.V, cloth.F), 0);
}

TEST(MeshCrossings, GridCountMatchesBruteForceOnRandomCrumpledMeshes) {
  const int n = 12;
  const wobble::SpringNetwork cloth = grid(n);
  const double h = 1.0 / (n - 1);
  long total = 0;
  for (unsigned seed : {1u, 2u, 3u, 4u, 5u}) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> jitter(-1.5 * h, 1.5 * h);
    Eigen::MatrixXd V = cloth.V;
    // Crumpled: a few sine folds in height, then every vertex moved by up to 1.5 edges.
    for (Eigen::Index i = 0; i < V.rows(); ++i) {
      V(i, 1) = 0.1 * std::sin(9.0 * V(i, 0)) * std::cos(7.0 * V(i, 2));
      for (int d = 0; d < 3; ++d)
        V(i, d) += jitter(random);
    }
    Eigen::MatrixXi edges;
    const long count = count_mesh_crossings(V, cloth.F, nullptr, &edges);
    EXPECT_EQ(count, brute_force_crossings(V, cloth.F, edges)) << "seed " << seed;
    total += count;
  }
  EXPECT_GT(total, 0);  // the meshes really cross themselves
}

TEST(MeshCrossings, LargeClothIsQuick) {
  // 128 × 128 vertices, 32,258 triangles, folded through itself. Timed for the report, not
  // asserted (timings are the benchmarks' business).
  const int n = 128;
  const wobble::SpringNetwork cloth = grid(n);
  const Eigen::MatrixXd V = fold_through(cloth, n, 80);
  const auto start = std::chrono::steady_clock::now();
  const long count = count_mesh_crossings(V, cloth.F);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ info ] 128x128 cloth: %ld crossings in %.1f ms\n", count, ms);
  RecordProperty("milliseconds", static_cast<int>(ms));
  EXPECT_GT(count, n);
}

}  // namespace

#include "sim/shapes/jelly_block.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <map>
#include <utility>

namespace {

double tet_volume(const Eigen::MatrixXd& V, const Eigen::RowVector4i& t) {
  const Eigen::Vector3d a = V.row(t(0)), b = V.row(t(1)), c = V.row(t(2)), d = V.row(t(3));
  return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

TEST(JellyBlock, TetrahedraFillTheCubeExactlyOnce) {
  wobble::JellyBlockOptions options;
  options.resolution = 3;
  options.size = 0.6;
  Eigen::MatrixXi T;
  const wobble::SpringNetwork jelly = wobble::make_jelly_block(options, &T);
  EXPECT_EQ(jelly.V.rows(), 4 * 4 * 4);
  ASSERT_EQ(T.rows(), 6 * 27);
  double volume = 0.0;
  for (Eigen::Index t = 0; t < T.rows(); ++t) {
    const double v = std::abs(tet_volume(jelly.V, T.row(t)));
    EXPECT_NEAR(v, 0.2 * 0.2 * 0.2 / 6.0, 1e-15) << "tet " << t;  // none degenerate
    volume += v;
  }
  EXPECT_NEAR(volume, 0.6 * 0.6 * 0.6, 1e-12);
  EXPECT_NEAR(jelly.m.sum(), options.density * 0.216, 1e-9);
}

TEST(JellyBlock, SpringsAreEdgesDiagonalsAndBodyDiagonals) {
  for (int cells : {1, 2, 5}) {
    wobble::JellyBlockOptions options;
    options.resolution = cells;
    const wobble::SpringNetwork jelly = wobble::make_jelly_block(options);
    const int n = cells + 1;
    // Axis edges, one diagonal per face of every cell, one main diagonal per cell.
    const int expected = 3 * n * n * cells + 3 * n * cells * cells + cells * cells * cells;
    EXPECT_EQ(jelly.E.rows(), expected) << cells << " cells";
  }
}

TEST(JellyBlock, BoundaryIsAClosedOutwardSurface) {
  wobble::JellyBlockOptions options;
  options.resolution = 3;
  const wobble::SpringNetwork jelly = wobble::make_jelly_block(options);
  ASSERT_EQ(jelly.F.rows(), 6 * 9 * 2);  // 6 sides, 9 squares each, 2 triangles per square
  // Closed and consistently oriented: every directed edge appears once, its reverse once.
  std::map<std::pair<int, int>, int> directed;
  const Eigen::Vector3d centre(0.0, options.size / 2, 0.0);
  double area = 0.0;
  for (Eigen::Index f = 0; f < jelly.F.rows(); ++f) {
    for (int c = 0; c < 3; ++c)
      ++directed[{jelly.F(f, c), jelly.F(f, (c + 1) % 3)}];
    const Eigen::Vector3d a = jelly.V.row(jelly.F(f, 0)), b = jelly.V.row(jelly.F(f, 1)),
                          c = jelly.V.row(jelly.F(f, 2));
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    EXPECT_GT(normal.dot((a + b + c) / 3 - centre), 0.0) << "face " << f << " faces inward";
    area += 0.5 * normal.norm();
  }
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(directed.count({edge.second, edge.first}), 1u);
  }
  EXPECT_NEAR(area, 6 * options.size * options.size, 1e-12);
}

TEST(JellyBlock, BottomFaceComesFirstAndStandsOnTheGround) {
  wobble::JellyBlockOptions options;
  options.resolution = 4;
  const wobble::SpringNetwork jelly = wobble::make_jelly_block(options);
  for (Eigen::Index i = 0; i < jelly.V.rows(); ++i) {
    EXPECT_EQ(jelly.V(i, 1) == 0.0, i < 25) << "vertex " << i;
  }
  EXPECT_NEAR(jelly.V.col(1).maxCoeff(), options.size, 1e-15);
}

}  // namespace

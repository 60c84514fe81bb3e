#include "sim/shapes/voronoi_masses.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace {

// Areas here are sums of a few products of small numbers: 1e-12 is far above their rounding
// and far below any hand-computed difference (the smallest is 0.25).
constexpr double tolerance = 1e-12;

Eigen::VectorXd one_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                             const Eigen::Vector3d& c) {
  Eigen::MatrixXd V(3, 3);
  V << a.transpose(), b.transpose(), c.transpose();
  Eigen::MatrixXi F(1, 3);
  F << 0, 1, 2;
  return wobble::voronoi_masses(V, F);
}

double triangle_area(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return 0.5 * (b - a).cross(c - a).norm();
}

TEST(VoronoiMasses, EquilateralTriangleSplitsInThirds) {
  const double side = 2.0;
  const Eigen::VectorXd areas =
      one_triangle(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(side, 0, 0),
                   Eigen::Vector3d(side / 2, side * std::sqrt(3.0) / 2, 0));
  const double area = std::sqrt(3.0) / 4 * side * side;
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(areas(i), area / 3, tolerance) << i;
}

TEST(VoronoiMasses, AcuteTriangleByHand) {
  // A = (0,0), B = (4,0), C = (1,3): area 6, cot A = 1/3, cot B = 1, cot C = 1/2,
  // |AB|² = 16, |AC|² = 10, |BC|² = 18.
  //   A: (16·½ + 10·1)/8 = 2.25   B: (16·½ + 18·⅓)/8 = 1.75   C: (10·1 + 18·⅓)/8 = 2
  const Eigen::VectorXd areas =
      one_triangle(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(4, 0, 0), Eigen::Vector3d(1, 3, 0));
  EXPECT_NEAR(areas(0), 2.25, tolerance);
  EXPECT_NEAR(areas(1), 1.75, tolerance);
  EXPECT_NEAR(areas(2), 2.0, tolerance);
}

TEST(VoronoiMasses, RightTriangleGivesHalfToTheRightAngle) {
  // 3-4-5 triangle, area 6: the circumcenter is the hypotenuse's midpoint, so the cotangent
  // formula gives the right-angle corner (16·¾ + 9·4/3)/8 = 3 and the others 16·¾/8 = 1.5.
  const Eigen::VectorXd areas =
      one_triangle(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(4, 0, 0), Eigen::Vector3d(0, 3, 0));
  EXPECT_NEAR(areas(0), 3.0, tolerance);
  EXPECT_NEAR(areas(1), 1.5, tolerance);
  EXPECT_NEAR(areas(2), 1.5, tolerance);
}

TEST(VoronoiMasses, ObtuseTriangleGivesHalfToTheObtuseCornerAndAQuarterToEachOther) {
  // A = (0,0), B = (4,0), C = (1,0.5): the angle at C is obtuse, area 1. The cotangent formula
  // (cot A = 2, cot B = 6, cot C = −1.375) would give A −1.8125, B −0.4375 and C 3.25; the
  // rule gives A 0.25, B 0.25, C 0.5.
  const Eigen::VectorXd areas =
      one_triangle(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(4, 0, 0), Eigen::Vector3d(1, 0.5, 0));
  EXPECT_NEAR(areas(0), 0.25, tolerance);
  EXPECT_NEAR(areas(1), 0.25, tolerance);
  EXPECT_NEAR(areas(2), 0.5, tolerance);
}

TEST(VoronoiMasses, AcuteTriangleMatchesItsCircumcenterRegions) {
  // Independent construction in 3-D: corner A's region is the quadrilateral A, mid(AB), O,
  // mid(AC) with O the circumcenter.
  const Eigen::Vector3d x[3] = {Eigen::Vector3d(0.1, -0.2, 0.3), Eigen::Vector3d(1.3, 0.4, -0.2),
                                Eigen::Vector3d(0.5, 1.1, 0.6)};
  const Eigen::Vector3d a = x[0] - x[2], b = x[1] - x[2];
  const Eigen::Vector3d normal = a.cross(b);
  const Eigen::Vector3d center =
      x[2] + (a.squaredNorm() * b - b.squaredNorm() * a).cross(normal) / (2 * normal.squaredNorm());
  const Eigen::VectorXd areas = one_triangle(x[0], x[1], x[2]);
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d& xi = x[i];
    const Eigen::Vector3d to_j = (xi + x[(i + 1) % 3]) / 2, to_k = (xi + x[(i + 2) % 3]) / 2;
    const double region = triangle_area(xi, to_j, center) + triangle_area(xi, center, to_k);
    EXPECT_NEAR(areas(i), region, tolerance) << i;
  }
}

TEST(VoronoiMasses, TotalIsTheMeshAreaAndScalesWithLengthSquared) {
  // A bumpy 5×5 grid whose diagonals alternate and whose shear makes some triangles obtuse.
  const int n = 5;
  Eigen::MatrixXd V(n * n, 3);
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c)
      V.row(r * n + c) << c + 0.7 * r, 0.3 * std::sin(1.7 * r + c), 0.8 * r;
  }
  Eigen::MatrixXi F(2 * (n - 1) * (n - 1), 3);
  int f = 0;
  for (int r = 0; r + 1 < n; ++r) {
    for (int c = 0; c + 1 < n; ++c) {
      const int v00 = r * n + c, v01 = v00 + 1, v10 = v00 + n, v11 = v10 + 1;
      if ((r + c) % 2 == 0) {
        F.row(f++) << v00, v01, v11;
        F.row(f++) << v00, v11, v10;
      } else {
        F.row(f++) << v00, v01, v10;
        F.row(f++) << v01, v11, v10;
      }
    }
  }
  double total = 0.0;
  int obtuse = 0;
  for (int t = 0; t < F.rows(); ++t) {
    const Eigen::Vector3d p = V.row(F(t, 0)), q = V.row(F(t, 1)), s = V.row(F(t, 2));
    total += triangle_area(p, q, s);
    if ((q - p).dot(s - p) < 0 || (p - q).dot(s - q) < 0 || (p - s).dot(q - s) < 0) ++obtuse;
  }
  ASSERT_GT(obtuse, 0) << "the mesh must exercise the obtuse rule";
  const Eigen::VectorXd areas = wobble::voronoi_masses(V, F);
  ASSERT_EQ(areas.size(), V.rows());
  EXPECT_NEAR(areas.sum(), total, 1e-12 * total);
  EXPECT_GT(areas.minCoeff(), 0.0);
  const Eigen::VectorXd scaled = wobble::voronoi_masses(3.0 * V, F);
  EXPECT_LE((scaled - 9.0 * areas).cwiseAbs().maxCoeff(), 1e-12 * scaled.maxCoeff());
}

TEST(VoronoiMasses, VertexInNoTriangleAndDegenerateTrianglesGetNothing) {
  Eigen::MatrixXd V(5, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5, 2, 0, 0;
  Eigen::MatrixXi F(2, 3);
  F << 0, 1, 2, 0, 1, 4;  // the second lies on a line: no area, no Voronoi region
  const Eigen::VectorXd areas = wobble::voronoi_masses(V, F);
  EXPECT_NEAR(areas.head(3).sum(), 0.5, tolerance);
  EXPECT_EQ(areas(3), 0.0);
  EXPECT_EQ(areas(4), 0.0);
  EXPECT_TRUE(areas.allFinite());
}

}  // namespace

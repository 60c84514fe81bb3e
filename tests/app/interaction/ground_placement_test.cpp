#include "app/interaction/ground_placement.h"

#include <gtest/gtest.h>

namespace {

// A vertical chain of `n` vertices 0.1 m apart hanging from the top, or a horizontal one.
Eigen::MatrixXd chain(int n, bool vertical) {
  Eigen::MatrixXd V(n, 3);
  for (int i = 0; i < n; ++i)
    V.row(i) =
        vertical ? Eigen::RowVector3d(0, 1.0 - 0.1 * i, 0) : Eigen::RowVector3d(0.1 * i, 1, 0);
  return V;
}
Eigen::MatrixXi chain_springs(int n) {
  Eigen::MatrixXi E(n - 1, 2);
  for (int i = 0; i + 1 < n; ++i)
    E.row(i) << i, i + 1;
  return E;
}

TEST(GroundPlacement, AGroundColliderDecides) {
  wobble::Collider low, high;
  low.height = -2.0;
  high.height = -0.5;
  wobble::Collider sphere;
  sphere.type = wobble::ColliderType::sphere;
  EXPECT_DOUBLE_EQ(
      wobble::ground_grid_height(chain(5, true), chain_springs(5), {0}, {sphere, low, high}), -0.5);
}

TEST(GroundPlacement, WithoutPinsTheRestMinimumLessTheMargin) {
  // Extent 0.4 m: margin 3% of it.
  EXPECT_NEAR(wobble::ground_grid_height(chain(5, true), chain_springs(5), {}, {}),
              0.6 - 0.03 * 0.4, 1e-12);
}

TEST(GroundPlacement, AHorizontalChainPinnedAtOneEndHangsItsFullLengthDown) {
  // 11 vertices over 1 m, pinned at x = 0: the far end can swing to 1.1 m (stretched) below.
  const double height = wobble::ground_grid_height(chain(11, false), chain_springs(11), {0}, {});
  EXPECT_NEAR(height, 1.0 - 1.1 * 1.0 - 0.03 * 1.0, 1e-9);
  // Pinned at both ends, the middle hangs at most half the length down.
  const double both = wobble::ground_grid_height(chain(11, false), chain_springs(11), {0, 10}, {});
  EXPECT_NEAR(both, 1.0 - 1.1 * 0.5 - 0.03, 1e-9);
}

TEST(GroundPlacement, PathsFollowTheSpringsNotStraightLines) {
  // A U: down 1 m, across 0.2 m, up 1 m, pinned at the top of the first arm. The top of the
  // second arm is 0.2 m from the pin in a straight line, but 2.2 m along the springs.
  Eigen::MatrixXd V(4, 3);
  V << 0, 1, 0,   //
      0, 0, 0,    //
      0.2, 0, 0,  //
      0.2, 1, 0;
  Eigen::MatrixXi E(3, 2);
  E << 0, 1, 1, 2, 2, 3;
  const double height = wobble::ground_grid_height(V, E, {0}, {});
  EXPECT_NEAR(height, 1.0 - 1.1 * 2.2 - 0.03 * 1.0, 1e-9);
}

TEST(GroundPlacement, NeverAboveTheRestMinimum) {
  // A vertex that no pin holds counts where it rests, far below the pinned chain.
  Eigen::MatrixXd V = chain(3, true);
  V.conservativeResize(4, 3);
  V.row(3) = Eigen::RowVector3d(5, -3, 0);  // a loose vertex far below
  const Eigen::MatrixXi E = chain_springs(3);
  const double height = wobble::ground_grid_height(V, E, {0}, {});
  EXPECT_LT(height, -3.0);
  EXPECT_NEAR(height, -3.0 - 0.03 * 5.0, 1e-9);
}

}  // namespace

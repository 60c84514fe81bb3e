// The pieces self-collision is built from: closest points and the spatial grid.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "sim/contact/closest_points.h"
#include "sim/contact/spatial_grid.h"

namespace {

using wobble::closest_on_segments;
using wobble::closest_on_triangle;

// The closest point by brute force: the best of a fine barycentric grid.
double sampled_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                        const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  double best = 1e300;
  const int n = 200;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; i + j <= n; ++j) {
      const double u = double(i) / n, v = double(j) / n;
      best = std::min(best, (p - ((1 - u - v) * a + u * b + v * c)).norm());
    }
  }
  return best;
}

TEST(ClosestPoints, OnATriangleFromEveryRegion) {
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  // Inside, beyond each edge, beyond each corner, and above.
  const std::vector<Eigen::Vector3d> points = {{0.2, 0.2, 0.5}, {0.5, -0.3, 0.1}, {-0.3, 0.5, -0.2},
                                               {0.8, 0.8, 0.0}, {-1, -1, 0},      {2, -0.1, 0.3},
                                               {-0.1, 2, 0.0}};
  for (const Eigen::Vector3d& p : points) {
    const Eigen::Vector3d alpha = closest_on_triangle(p, a, b, c);
    EXPECT_NEAR(alpha.sum(), 1.0, 1e-12);
    EXPECT_GE(alpha.minCoeff(), 0.0);
    const double distance = (p - (alpha(0) * a + alpha(1) * b + alpha(2) * c)).norm();
    EXPECT_NEAR(distance, sampled_distance(p, a, b, c), 1e-2) << p.transpose();
    EXPECT_LE(distance, sampled_distance(p, a, b, c) + 1e-12) << p.transpose();
  }
  // Inside, straight above: the foot of the perpendicular.
  EXPECT_TRUE(
      closest_on_triangle({0.2, 0.3, 1.0}, a, b, c).isApprox(Eigen::Vector3d(0.5, 0.2, 0.3)));
}

TEST(ClosestPoints, OnADegenerateTriangleItsClosestEdge) {
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(2, 0, 0);
  const Eigen::Vector3d alpha = closest_on_triangle({1.5, 1.0, 0.0}, a, b, c);
  EXPECT_TRUE((alpha(0) * a + alpha(1) * b + alpha(2) * c).isApprox(Eigen::Vector3d(1.5, 0, 0)));
}

TEST(ClosestPoints, OfTwoSegments) {
  // Crossing at right angles one above the other.
  Eigen::Vector2d su = closest_on_segments({-1, 0, 0}, {1, 0, 0}, {0, -1, 1}, {0, 1, 1});
  EXPECT_NEAR(su(0), 0.5, 1e-12);
  EXPECT_NEAR(su(1), 0.5, 1e-12);
  // Beyond an end of the first: clamped to it.
  su = closest_on_segments({0, 0, 0}, {1, 0, 0}, {2, -1, 0}, {2, 1, 0});
  EXPECT_EQ(su(0), 1.0);
  EXPECT_NEAR(su(1), 0.5, 1e-12);
  // Parallel, overlapping: a pair of points one unit apart.
  su = closest_on_segments({0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {3, 1, 0});
  const Eigen::Vector3d p = Eigen::Vector3d(0, 0, 0) + su(0) * Eigen::Vector3d(2, 0, 0);
  const Eigen::Vector3d q = Eigen::Vector3d(1, 1, 0) + su(1) * Eigen::Vector3d(2, 0, 0);
  EXPECT_NEAR((p - q).norm(), 1.0, 1e-12);
  // A point for a segment.
  su = closest_on_segments({0, 0, 0}, {0, 0, 0}, {-1, 1, 0}, {1, 1, 0});
  EXPECT_NEAR(su(1), 0.5, 1e-12);
}

TEST(SpatialGrid, FindsEveryOverlappingPairOnceAndNoOther) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> where(-1.0, 1.0), size(0.0, 0.2);
  std::vector<Eigen::AlignedBox3d> boxes;
  for (int i = 0; i < 400; ++i) {
    const Eigen::Vector3d low(where(random), where(random), where(random));
    boxes.emplace_back(low, low + Eigen::Vector3d(size(random), size(random), size(random)));
  }
  // Two large boxes, on the list every query visits.
  boxes.emplace_back(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1));
  boxes.emplace_back(Eigen::Vector3d(-0.5, -2, -0.5), Eigen::Vector3d(0.5, 2, 0.5));
  wobble::SpatialGrid grid(0.05);
  grid.build(boxes);
  std::set<std::pair<int, int>> expected, found;
  for (int i = 0; i < int(boxes.size()); ++i) {
    for (int j = i + 1; j < int(boxes.size()); ++j) {
      if (boxes[i].intersects(boxes[j])) expected.emplace(i, j);
    }
  }
  int visits = 0;
  grid.for_each_overlapping_pair([&](int i, int j) {
    ++visits;
    EXPECT_LT(i, j);
    found.emplace(i, j);
  });
  EXPECT_EQ(found, expected);
  EXPECT_EQ(visits, int(found.size()));  // each once
  // Candidates of one box include every box it overlaps.
  std::set<int> candidates;
  grid.for_each_candidate(boxes[3], [&](int id) { candidates.insert(id); });
  for (int j = 0; j < int(boxes.size()); ++j) {
    if (boxes[3].intersects(boxes[j])) {
      EXPECT_TRUE(candidates.count(j)) << j;
    }
  }
}

}  // namespace

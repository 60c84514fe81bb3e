// The pieces self-collision is built from: closest points, the spatial grid and the rest
// neighbours.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "sim/contact/closest_points.h"
#include "sim/contact/self_collision_surface.h"
#include "sim/contact/self_contact_proximity.h"
#include "sim/contact/self_contact_term.h"
#include "sim/contact/spatial_grid.h"
#include "sim/simulation.h"

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

// Every query visits each box it overlaps exactly once, and no other beyond single precision's
// rounding: boxes in many cells, boxes too large for a cell (the few every query visits), empty
// boxes, boxes that just touch or just miss a query, and a query covering the whole grid.
TEST(SpatialGrid, VisitsEveryOverlappingBoxOnceAndNoOther) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> where(-1.0, 1.0), size(0.0, 0.2);
  std::vector<Eigen::AlignedBox3d> boxes;
  for (int i = 0; i < 400; ++i) {
    const Eigen::Vector3d low(where(random), where(random), where(random));
    boxes.emplace_back(low, low + Eigen::Vector3d(size(random), size(random), size(random)));
  }
  boxes.emplace_back(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1));
  boxes.emplace_back(Eigen::Vector3d(-0.5, -2, -0.5), Eigen::Vector3d(0.5, 2, 0.5));
  boxes.emplace_back();  // empty: never visited
  // Touching the first box's low x face, and a millimetre short of it.
  const Eigen::AlignedBox3d first = boxes[0];
  boxes.emplace_back(first.min() - Eigen::Vector3d(0.01, 0, 0),
                     Eigen::Vector3d(first.min().x(), first.max().y(), first.max().z()));
  boxes.emplace_back(first.min() - Eigen::Vector3d(0.01, 0, 0),
                     Eigen::Vector3d(first.min().x() - 1e-3, first.max().y(), first.max().z()));
  wobble::SpatialGrid grid;
  grid.build(boxes, 0.05);
  std::vector<Eigen::AlignedBox3d> queries(boxes.begin(), boxes.begin() + 40);
  queries.emplace_back(Eigen::Vector3d(-3, -3, -3), Eigen::Vector3d(3, 3, 3));
  for (const Eigen::AlignedBox3d& query : queries) {
    std::map<int, int> visits;
    grid.for_each_overlapping(query, [&](int id, const Eigen::AlignedBox3f& filed) {
      ++visits[id];
      // As filed: holding the box, in single precision.
      EXPECT_TRUE(filed.cast<double>().contains(boxes[id])) << "box " << id;
      return true;
    });
    // Within rounding: a millionth of the coordinates (about 10 float roundings).
    Eigen::AlignedBox3d near = query;
    near.min().array() -= 1e-6 * query.min().cwiseAbs().maxCoeff() + 1e-30;
    near.max().array() += 1e-6 * query.max().cwiseAbs().maxCoeff() + 1e-30;
    for (int id = 0; id < int(boxes.size()); ++id) {
      const int count = visits.count(id) ? visits[id] : 0;
      if (!boxes[id].isEmpty() && query.intersects(boxes[id])) {
        EXPECT_EQ(count, 1) << "box " << id;
      } else if (boxes[id].isEmpty() || !near.intersects(boxes[id])) {
        EXPECT_EQ(count, 0) << "box " << id;
      } else {
        EXPECT_LE(count, 1) << "box " << id;
      }
    }
  }
}

// Boxes far larger than the cell asked for, and boxes of every size at once: each is filed once
// (on the level its size needs), so the memory stays O(boxes), and queries still find them.
TEST(SpatialGrid, FilesBoxesOfAnySizeOnce) {
  std::vector<Eigen::AlignedBox3d> boxes;
  for (int i = 0; i < 1000; ++i)
    boxes.emplace_back(Eigen::Vector3d(i * 1e-3, 0, 0), Eigen::Vector3d(1 + i * 1e-3, 1, 1));
  for (int i = 0; i < 1000; ++i) {
    const double size = std::pow(10.0, -4 + i % 8);
    boxes.emplace_back(Eigen::Vector3d(i, 0, 0), Eigen::Vector3d(i + size, size, size));
  }
  wobble::SpatialGrid grid;
  grid.build(boxes, 1e-3);
  // One entry a box (40 bytes), and hash slots of an int each.
  EXPECT_LT(grid.memory_bytes(), boxes.size() * 72);
  int visited = 0;
  grid.for_each_overlapping(boxes[0], [&](int id) {
    visited += id < 1000;
    return true;
  });
  EXPECT_EQ(visited, 1000);
}

// A pair is a rest neighbour when its features are closer than the reach in the rest shape:
// near a corner (the answer from the corners alone) and in the middle of a face or of two edges
// (from the closest points), just inside and just outside.
TEST(RestNeighbours, ArePairsCloserThanTheReachInTheRestShape) {
  wobble::SpringNetwork network;
  network.V.resize(10, 3);
  network.V << 0, 0, 0, 1, 0, 0, 0, 1, 0,  // a triangle of 1 m in the z = 0 plane
      0.25, 0.25, 0.004,                   // 4 mm above its face, far from every corner
      0.25, 0.25, 0.006,                   // 6 mm above it
      -0.003, 0, 0,                        // 3 mm from its first corner
      0.5, -0.5, 0.004, 0.5, 0.5, 0.004,   // an edge 4 mm above the first edge's middle
      0.5, -0.5, 0.006, 0.5, 0.5, 0.006;   // and one 6 mm above it
  network.F.resize(4, 3);
  network.F << 0, 1, 2, 3, 4, 5, 6, 7, 3, 8, 9, 4;  // so that every vertex is on the surface
  const wobble::SelfCollisionSurface surface(network);
  const auto edge = [&](int a, int b) {
    for (Eigen::Index e = 0; e < surface.edges.rows(); ++e) {
      if (surface.edges(e, 0) == std::min(a, b) && surface.edges(e, 1) == std::max(a, b))
        return static_cast<int>(e);
    }
    ADD_FAILURE() << "no edge " << a << "-" << b;
    return 0;
  };
  const wobble::RestNeighbours rest(surface, 0.005), none;
  EXPECT_TRUE(rest.vertex_triangle(surface, 3, 0));
  EXPECT_FALSE(rest.vertex_triangle(surface, 4, 0));
  EXPECT_TRUE(rest.vertex_triangle(surface, 5, 0));
  EXPECT_TRUE(rest.edge_edge(surface, edge(0, 1), edge(6, 7)));
  EXPECT_FALSE(rest.edge_edge(surface, edge(0, 1), edge(8, 9)));
  EXPECT_FALSE(none.vertex_triangle(surface, 3, 0));
  EXPECT_FALSE(none.edge_edge(surface, edge(0, 1), edge(6, 7)));
}

// n triangles on the same three points (each with vertices of its own, and a metre apart in the
// rest shape, so that they are no rest neighbours), falling 1 cm in a step at the largest
// thickness: self-contact's pairs and memory grow with the mesh, not with its square (one pile
// of coincident triangles took 9.4 GB when skipped boxes went uncounted), and the step creates
// no crossing (every distance is 0, so every bound is 0: the pile moves only as a whole).
struct CoincidentRun {
  std::size_t memory = 0;
  double pairs = 0.0;
  Eigen::MatrixXd start, end;
};

CoincidentRun run_coincident(int n) {
  wobble::SpringNetwork network;
  network.V.resize(3 * n, 3);
  network.F.resize(n, 3);
  network.E.resize(3 * n, 2);
  Eigen::MatrixXd coincident(3 * n, 3);
  for (int t = 0; t < n; ++t) {
    coincident.row(3 * t) << 0.0, 0.5, 0.0;
    coincident.row(3 * t + 1) << 0.1, 0.5, 0.0;
    coincident.row(3 * t + 2) << 0.0, 0.5, 0.1;
    for (int k = 0; k < 3; ++k)
      network.V.row(3 * t + k) = coincident.row(3 * t + k) + Eigen::RowVector3d(t, 0.0, 0.0);
    network.F.row(t) << 3 * t, 3 * t + 1, 3 * t + 2;
    network.E.row(3 * t) << 3 * t, 3 * t + 1;
    network.E.row(3 * t + 1) << 3 * t + 1, 3 * t + 2;
    network.E.row(3 * t + 2) << 3 * t + 2, 3 * t;
  }
  network.m = Eigen::VectorXd::Constant(3 * n, 1e-3);
  wobble::SimulationParams params;
  params.self_collision.on = true;
  params.self_collision.thickness = 1.0;
  params.iterations = 3;
  wobble::Simulation simulation(network, {}, params);
  Eigen::MatrixXd previous = coincident;
  previous.col(1).array() += 0.01;  // falling 1 cm in a step
  simulation.set_state(coincident, previous);
  CoincidentRun run;
  run.start = simulation.positions();
  EXPECT_EQ(simulation.step(), wobble::StepStatus::ok);
  run.end = simulation.positions();
  run.pairs = simulation.last_step_timing().figure("self-contact", "pairs");
  run.memory = simulation.term<wobble::SelfContactTerm>()->memory_bytes();
  return run;
}

TEST(SelfContact, CoincidentTrianglesStayBoundedByTheMesh) {
  const CoincidentRun small = run_coincident(500), large = run_coincident(2000);
  // Each vertex and each edge keeps at most max_pairs_per_feature pairs.
  const int cap = wobble::SelfContactProximity::max_pairs_per_feature;
  EXPECT_LE(large.pairs, cap * (3 * 2000 + 3 * 2000));
  EXPECT_GT(large.pairs, 0);
  // Four times the triangles: at most about four times the memory (all pairs: sixteen times).
  EXPECT_LT(static_cast<double>(large.memory), 5.0 * static_cast<double>(small.memory))
      << small.memory << " bytes for 500 triangles, " << large.memory << " for 2,000";
  // Every triangle fell alike: they still coincide, so no edge passes through a triangle.
  const Eigen::RowVector3d moved = large.end.row(0) - large.start.row(0);
  EXPECT_LT(moved(1), -0.001) << "the pile fell";
  for (Eigen::Index v = 0; v < large.end.rows(); ++v)
    EXPECT_LT((large.end.row(v) - large.start.row(v) - moved).norm(), 1e-9) << v;
}

}  // namespace

// Self-contact proximity under load: the same answer on any number of threads, and bounded
// time, memory and a safe answer where a query meets more than it may look at.
#include <gtest/gtest.h>

#include <vector>

#include "self_contact_proximity_meshes.h"
#include "sim/contact/self_contact_proximity.h"

namespace {

using wobble::SelfContactPair;
using wobble::SelfContactProximity;
using namespace wobble::testing;

TEST(SelfContactProximity, SameResultsOnOneAndSeveralThreads) {
  const Mesh mesh = accordion(30, 3);
  wobble::WorkerPool one(1), several(4);
  const Eigen::VectorXd reach = constant_reach(mesh, 0.005);
  const Found alone(mesh, reach, 0.005, 0.0, &one);
  ASSERT_GT(alone.pairs.size(), 1000u);
  for (int run = 0; run < 8; ++run) {
    const Found shared(mesh, reach, 0.005, 0.0, &several);
    EXPECT_TRUE(same(alone.pairs, shared.pairs)) << run;
    EXPECT_EQ(alone.bounds, shared.bounds) << run;
  }
  EXPECT_GT(several.helper_tasks(), 0) << "the helpers should have taken part";
}

// A 60×60 grid with every vertex at one point: every query meets thousands of features, stops,
// and freezes them; the pairs stay at most 32 a feature and the buffers O(features).
TEST(SelfContactProximity, ACoincidentGridIsBoundedAndFrozen) {
  Mesh mesh;
  mesh.add_grid(60, 0.01, Eigen::Vector3d::Zero());
  for (Eigen::Vector3d& v : mesh.vertices)
    v = Eigen::Vector3d(0.1, 0.2, 0.3);
  const wobble::SelfCollisionSurface surface(mesh.network());
  const wobble::RestNeighbours rest;
  wobble::WorkerPool one(1), several(3);
  SelfContactProximity proximity(&several), alone(&one);
  std::vector<SelfContactPair> pairs, pairs_alone;
  Eigen::VectorXd bounds, bounds_alone;
  const Eigen::VectorXd reach = constant_reach(mesh, 0.01);
  proximity.find(surface, rest, mesh.x(), reach, 0.005, pairs, bounds);
  EXPECT_TRUE(proximity.saturated());
  EXPECT_EQ(bounds.maxCoeff(), 0.0);
  const std::size_t features = surface.vertices.size() + surface.edges.rows();
  EXPECT_LE(pairs.size(), SelfContactProximity::max_pairs_per_feature * features);
  for (const SelfContactPair& pair : pairs)
    ASSERT_NEAR(pair.normal.norm(), 1.0, 1e-12) << "a stable normal at distance 0";
  // The chunks' pairs (at most 32 a feature, with a vector's doubling), and a kilobyte a
  // feature for the grids and boxes: O(features), where all pairs would be 3600 × 7000.
  const std::size_t memory = proximity.memory_bytes();
  EXPECT_LT(memory,
            features *
                (2 * SelfContactProximity::max_pairs_per_feature * sizeof(SelfContactPair) + 1000));
  proximity.find(surface, rest, mesh.x(), reach, 0.005, pairs, bounds);
  EXPECT_EQ(proximity.memory_bytes(), memory) << "warmed up: the buffers do not grow";
  alone.find(surface, rest, mesh.x(), reach, 0.005, pairs_alone, bounds_alone);
  EXPECT_TRUE(same(pairs, pairs_alone));
}

// A probe 3 mm above a stack of coincident triangles, more than a query may meet: its query
// stops before it has seen them all, so it is frozen (b = 0) rather than trusted with half of
// 3 mm; far away, a triangle keeps its reach.
TEST(SelfContactProximity, AQueryThatStopsFreezesItsNeighbourhood) {
  const int stack = SelfContactProximity::max_met + 100;
  Mesh mesh;
  for (int k = 0; k < stack; ++k)
    mesh.add_triangle({0, 0, 0}, {0.01, 0, 0}, {0, 0.01, 0});
  add_probe(mesh, {0.002, 0.002, 0.003});
  mesh.add_triangle({1, 1, 1}, {1.01, 1, 1}, {1, 1.01, 1});
  const Found found(mesh, constant_reach(mesh, 0.01), 0.005);
  EXPECT_EQ(found.bounds(3 * stack), 0.0);
  EXPECT_FALSE(found.covers) << "the pairs among the frozen vertices went unexamined";
  for (int v = 3 * stack + 3; v < 3 * stack + 6; ++v)
    EXPECT_NEAR(found.bounds(v), found.bound(0.01), 1e-15);
  // With fewer than max_met triangles below, the probe is trusted with half its distance.
  Mesh few;
  for (int k = 0; k < 100; ++k)
    few.add_triangle({0, 0, 0}, {0.01, 0, 0}, {0, 0.01, 0});
  add_probe(few, {0.002, 0.002, 0.003});
  const Found near(few, constant_reach(few, 0.01), 0.005);
  EXPECT_NEAR(near.bounds(300), near.bound(0.0015), 1e-15);
}

}  // namespace

// Self-contact proximity: the pairs closer than the contact distance, the bounds on each
// vertex's motion that keep the surface from passing through itself, and clamping to them.
#include "sim/contact/self_contact_proximity.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <tuple>
#include <vector>

#include "mesh_crossings.h"
#include "self_contact_proximity_meshes.h"

namespace {

using wobble::SelfContactPair;
using wobble::SelfContactProximity;
using wobble::vertex_row;
using namespace wobble::testing;

TEST(SelfContactProximity, AVertexNearATriangleIsOnePairWithItsClosestPoint) {
  for (const double height : {0.004, 0.006}) {
    Mesh mesh;
    mesh.add_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    add_probe(mesh, {0.2, 0.3, height});
    const Found found(mesh, constant_reach(mesh, 0.01), 0.005);
    if (height > 0.005) {
      EXPECT_TRUE(found.pairs.empty()) << "a vertex 6 mm away, beyond 5 mm";
      continue;
    }
    ASSERT_EQ(found.pairs.size(), 1u);
    const SelfContactPair& pair = found.pairs[0];
    EXPECT_TRUE(pair.vertex_triangle);
    EXPECT_EQ(pair.vertex[0], 3);
    const double expected[4] = {1.0, -0.5, -0.2, -0.3};  // the foot of the perpendicular
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(pair.vertex[k], k == 0 ? 3 : k - 1);
      EXPECT_NEAR(pair.beta[k], expected[k], 1e-12) << k;  // rounding of the barycentrics
    }
    EXPECT_TRUE(pair.normal.isApprox(Eigen::Vector3d::UnitZ(), 1e-12));
    EXPECT_NEAR(pair.depth, height, 1e-15);  // the distance at x
  }
}

TEST(SelfContactProximity, TwoSkewEdgesAreOnePair) {
  for (const double height : {0.004, 0.006}) {
    Mesh mesh;  // one triangle hangs in y = 0 below the x axis, one stands in x = 0 above
    mesh.add_triangle({-1, 0, 0}, {1, 0, 0}, {0, 0, -1});
    mesh.add_triangle({0, -1, height}, {0, 1, height}, {0, 0, height + 1});
    const Found found(mesh, constant_reach(mesh, 0.01), 0.005);
    if (height > 0.005) {
      EXPECT_TRUE(found.pairs.empty());
      continue;
    }
    ASSERT_EQ(found.pairs.size(), 1u);
    const SelfContactPair& pair = found.pairs[0];
    EXPECT_FALSE(pair.vertex_triangle);
    const int vertices[4] = {0, 1, 3, 4};
    const double beta[4] = {0.5, 0.5, -0.5, -0.5};
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(pair.vertex[k], vertices[k]);
      EXPECT_NEAR(pair.beta[k], beta[k], 1e-12);
    }
    // From the second edge (above) to the first: down.
    EXPECT_TRUE(pair.normal.isApprox(-Eigen::Vector3d::UnitZ(), 1e-12));
    EXPECT_NEAR(pair.depth, height, 1e-15);
  }
}

// A 4×4 grid crumpled into a 1 cm cube: every pair closer than the contact distance that shares
// no vertex, with its distance and normal, and no other (no feature has more than 32).
TEST(SelfContactProximity, PairsAreExactlyTheCloseOnesSharingNoVertex) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> in_cube(0.0, 0.01);
  for (int trial = 0; trial < 5; ++trial) {
    Mesh mesh;
    mesh.add_grid(4, 0.01, Eigen::Vector3d::Zero());
    for (Eigen::Vector3d& v : mesh.vertices)
      v = Eigen::Vector3d(in_cube(random), in_cube(random), in_cube(random));
    const double contact = 0.004;
    const Found found(mesh, constant_reach(mesh, 0.002), contact);
    std::map<std::tuple<bool, int, int, int, int>, double> expected;
    for (int v = 0; v < 16; ++v) {
      for (const Eigen::Vector3i& t : mesh.triangles) {
        if (v == t(0) || v == t(1) || v == t(2)) continue;
        const double d = vertex_triangle_distance(found.x, v, t);
        if (d < contact) expected[{true, v, t(0), t(1), t(2)}] = d;
      }
    }
    const Eigen::MatrixXi& E = found.surface.edges;
    for (int e = 0; e < E.rows(); ++e) {
      for (int f = e + 1; f < E.rows(); ++f) {
        if (E(e, 0) == E(f, 0) || E(e, 0) == E(f, 1) || E(e, 1) == E(f, 0) || E(e, 1) == E(f, 1))
          continue;
        const double d = edge_edge_distance(found.x, E(e, 0), E(e, 1), E(f, 0), E(f, 1));
        if (d < contact) expected[{false, E(e, 0), E(e, 1), E(f, 0), E(f, 1)}] = d;
      }
    }
    ASSERT_GT(expected.size(), 10u) << "the trial should have pairs to find";
    EXPECT_EQ(found.pairs.size(), expected.size());
    for (const SelfContactPair& pair : found.pairs) {
      EXPECT_FALSE(share_vertex(pair));
      const auto key = std::make_tuple(pair.vertex_triangle, pair.vertex[0], pair.vertex[1],
                                       pair.vertex[2], pair.vertex[3]);
      ASSERT_EQ(expected.count(key), 1u) << "a pair that is not close";
      EXPECT_NEAR(pair.depth, expected[key], 1e-15);
      Eigen::Vector3d q = Eigen::Vector3d::Zero();
      for (int k = 0; k < 4; ++k)
        q += pair.beta[k] * vertex_row(found.x, pair.vertex[k]);
      EXPECT_NEAR(q.norm(), pair.depth, 1e-15);
      EXPECT_NEAR(pair.normal.dot(q), pair.depth, 1e-15);  // unit, along q
    }
  }
}

TEST(SelfContactProximity, RestNeighboursAreNoPairsButLowerTheBounds) {
  Mesh mesh;
  mesh.add_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  add_probe(mesh, {0.2, 0.3, 0.004});
  const Eigen::VectorXd reach = constant_reach(mesh, 0.01);
  const Found strangers(mesh, reach, 0.005, 0.0);
  const Found neighbours(mesh, reach, 0.005, 0.01);  // the rest shape is x: 4 mm apart
  EXPECT_EQ(strangers.pairs.size(), 1u);
  EXPECT_TRUE(neighbours.pairs.empty());
  for (const Found* found : {&strangers, &neighbours}) {
    EXPECT_NEAR(found->bounds(3), found->bound(0.002), 1e-15);  // half the 4 mm, not the 1 cm reach
    EXPECT_NEAR(found->bounds(0), found->bound(0.002), 1e-15);  // a corner of the triangle below
  }
}

TEST(SelfContactProximity, AFarVertexMayMoveItsReach) {
  Mesh mesh;
  mesh.add_triangle({0, 0, 0}, {0.01, 0, 0}, {0, 0.01, 0});
  mesh.add_triangle({1, 1, 1}, {1.01, 1, 1}, {1, 1.01, 1});
  mesh.vertices.push_back({0.5, 0.5, 0.5});  // on no triangle
  const Eigen::VectorXd reach =
      (Eigen::VectorXd(7) << 0.01, 0.02, 0.03, 0.0, 0.05, 0.1, 1).finished();
  const Found found(mesh, reach, 0.005);
  for (int v = 0; v < 6; ++v)
    EXPECT_NEAR(found.bounds(v), found.bound(reach(v)), 1e-15) << v;
  EXPECT_EQ(found.bounds(6), std::numeric_limits<double>::infinity());
}

// Reaches that differ: a vertex with a long reach 4 mm above a triangle whose corners have short
// ones, then the other way round, beside a far grid of short reaches that sets the common search
// floor low. Whichever side reaches, the pair counts for both, at its 4 mm.
TEST(SelfContactProximity, ALongReachOnEitherSideFindsThePair) {
  for (const bool probe_reaches : {true, false}) {
    Mesh mesh;
    mesh.add_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    add_probe(mesh, {0.2, 0.3, 0.004});
    mesh.add_grid(5, 0.05, Eigen::Vector3d(5, 5, 5));
    Eigen::VectorXd reach = constant_reach(mesh, 0.001);
    for (int v = 0; v < 3; ++v)
      reach(probe_reaches ? 3 : v) = 0.01;
    const Found found(mesh, reach, 0.002);
    EXPECT_TRUE(found.pairs.empty());  // 4 mm: beyond the contact distance
    // Half the 4 mm, or the vertex's own 1 mm reach where that is less.
    EXPECT_NEAR(found.bounds(3), found.bound(probe_reaches ? 0.002 : 0.001), 1e-15);
    EXPECT_NEAR(found.bounds(0), found.bound(probe_reaches ? 0.001 : 0.002), 1e-15);
  }
}

// Two jittered parallel 6×6 grids a few mm apart with random reaches: every pair that shares no
// vertex (rest neighbours within each grid included) stays apart however each vertex moves within
// its bound, and the bounds are the formula's, by brute force.
TEST(SelfContactProximity, BoundsKeepEveryPairApart) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> jitter(-0.001, 0.001), reach_of(0.0, 0.012);
  std::uniform_int_distribution<int> one_in(0, 6);
  for (int trial = 0; trial < 8; ++trial) {
    // Odd trials: mostly 1 mm reaches and a few of 12 mm, layers 5 mm apart, so that the search
    // must reach farther around some vertices than around most.
    const bool mixed = trial % 2 == 1;
    Mesh mesh;
    mesh.add_grid(6, 0.01, Eigen::Vector3d::Zero());
    mesh.add_grid(6, 0.01, Eigen::Vector3d(0.003, 0.004, mixed ? 0.005 : 0.004));
    for (Eigen::Vector3d& v : mesh.vertices)
      v += Eigen::Vector3d(jitter(random), jitter(random), jitter(random));
    Eigen::VectorXd reach(mesh.vertices.size());
    for (Eigen::Index v = 0; v < reach.size(); ++v) {
      if (mixed) {
        reach(v) = one_in(random) == 0 ? 0.012 : 0.001;
      } else {
        reach(v) = v % 7 == 0 ? 0.0 : reach_of(random);
      }
    }
    const Found found(mesh, reach, mixed ? 0.003 : 0.004, 0.015);
    const Eigen::VectorXd& b = found.bounds;
    // The formula: min(2R_v, each found pair's distance) per vertex, then γ/2 of it.
    Eigen::VectorXd nearest = 2.0 * reach;
    const auto box_of = [&](std::initializer_list<int> vertices) {
      Eigen::AlignedBox3d box;
      for (const int v : vertices)
        box.extend(vertex_row(found.x, v));
      return box;
    };
    const auto apart = [&](const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& c, double r) {
      return !a.intersects(Eigen::AlignedBox3d(c.min().array() - r, c.max().array() + r));
    };
    int pairs = 0;
    for (int v = 0; v < found.x.rows(); ++v) {
      for (const Eigen::Vector3i& t : mesh.triangles) {
        if (v == t(0) || v == t(1) || v == t(2)) continue;
        const double d = vertex_triangle_distance(found.x, v, t);
        EXPECT_LT(b(v) + std::max({b(t(0)), b(t(1)), b(t(2))}), d) << v;
        const double r = reach(v) + std::max({reach(t(0)), reach(t(1)), reach(t(2))});
        if (apart(box_of({v}), box_of({t(0), t(1), t(2)}), r)) continue;
        for (const int u : {v, t(0), t(1), t(2)})
          nearest(u) = std::min(nearest(u), d);
        ++pairs;
      }
    }
    const Eigen::MatrixXi& E = found.surface.edges;
    for (int e = 0; e < E.rows(); ++e) {
      for (int f = e + 1; f < E.rows(); ++f) {
        const int p0 = E(e, 0), p1 = E(e, 1), q0 = E(f, 0), q1 = E(f, 1);
        if (p0 == q0 || p0 == q1 || p1 == q0 || p1 == q1) continue;
        const double d = edge_edge_distance(found.x, p0, p1, q0, q1);
        EXPECT_LT(std::max(b(p0), b(p1)) + std::max(b(q0), b(q1)), d) << e << " " << f;
        const double r = std::max(reach(p0), reach(p1)) + std::max(reach(q0), reach(q1));
        if (apart(box_of({p0, p1}), box_of({q0, q1}), r)) continue;
        for (const int u : {p0, p1, q0, q1})
          nearest(u) = std::min(nearest(u), d);
        ++pairs;
      }
    }
    EXPECT_GT(pairs, mixed ? 200 : 1000) << "the reaches should find many pairs";
    // The same distances by the same formulas: equal to rounding.
    for (int v = 0; v < found.x.rows(); ++v)
      EXPECT_NEAR(b(v), found.bound(0.5 * nearest(v)), 1e-15) << v;
  }
}

// Two grids 4 mm apart moved toward each other by up to 8 mm each (and all of it carried by a
// common motion): they pass through each other, unless clamped to the bounds.
TEST(SelfContactProximity, ClampedMotionNeverCrosses) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> closing(0.0, 0.008), sideways(-0.002, 0.002);
  const Eigen::Vector3d common(0.03, -0.02, 0.01);
  for (int trial = 0; trial < 4; ++trial) {
    Mesh mesh;
    mesh.add_grid(6, 0.01, Eigen::Vector3d::Zero());
    mesh.add_grid(6, 0.01, Eigen::Vector3d(0.005, 0.005, 0.004));
    const Found found(mesh, constant_reach(mesh, 0.006), 0.004, 0.015);
    Eigen::MatrixXd p = found.x;
    for (int v = 0; v < p.rows(); ++v) {
      const double up = v < 36 ? closing(random) : -closing(random);
      p.row(v) += (common + Eigen::Vector3d(sideways(random), sideways(random), up)).transpose();
    }
    Eigen::MatrixXi F(mesh.triangles.size(), 3);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      F.row(t) = mesh.triangles[t].transpose();
    // The most crossings at 50 points along the straight path from x to p.
    const auto crossings_on_the_way = [&](const Eigen::MatrixXd& to) {
      long most = 0;
      for (int k = 1; k <= 50; ++k) {
        const Eigen::MatrixXd at = found.x + (k / 50.0) * (to - found.x);
        most = std::max(most, wobble::testing::count_mesh_crossings(at, F));
      }
      return most;
    };
    EXPECT_GT(crossings_on_the_way(p), 0) << "unclamped, the grids should pass through";
    Eigen::MatrixXd clamped = p;
    const int moved = wobble::clamp_to_bounds(found.x, common, found.bounds, clamped);
    EXPECT_EQ(crossings_on_the_way(clamped), 0);
    int beyond = 0;
    for (int v = 0; v < p.rows(); ++v) {
      const Eigen::Vector3d from = vertex_row(found.x, v) + common;
      const double wanted = (vertex_row(p, v) - from).norm();
      beyond += wanted > found.bounds(v);
      EXPECT_LE((vertex_row(clamped, v) - from).norm(), found.bounds(v)) << v;
      if (wanted <= found.bounds(v)) {
        EXPECT_EQ(clamped.row(v), p.row(v)) << v;
      }
    }
    EXPECT_EQ(moved, beyond);
    EXPECT_GT(moved, 0);
  }
}

// Two small triangles 4 mm apart, a kilometre from the origin (where a coordinate rounds to about
// 10⁻¹³ m), the upper one pushed 1 cm down through the lower at every epoch and held back by
// the bounds: the gap shrinks epoch after epoch, but never below the floor (without one it keeps
// halving, below the floor by epoch 21, on towards the rounding of the coordinates, where
// rounding alone decides on which side of a triangle a vertex lies).
TEST(SelfContactProximity, APairPressedTogetherEpochAfterEpochStaysAboveTheFloor) {
  const Eigen::Vector3d far(1000.0, 1000.0, 1000.0);
  Mesh mesh;
  mesh.add_triangle(far, far + Eigen::Vector3d(0.01, 0, 0), far + Eigen::Vector3d(0, 0.01, 0));
  mesh.add_triangle(far + Eigen::Vector3d(0.002, 0.002, 0.004),
                    far + Eigen::Vector3d(0.008, 0.002, 0.004),
                    far + Eigen::Vector3d(0.002, 0.008, 0.004));
  Eigen::MatrixXi F(2, 3);
  F << 0, 1, 2, 3, 4, 5;
  const Eigen::VectorXd reach = constant_reach(mesh, 0.01);
  Eigen::MatrixXd x = mesh.x();
  const wobble::SelfCollisionSurface surface(mesh.network());
  const wobble::RestNeighbours rest;
  SelfContactProximity proximity;
  std::vector<SelfContactPair> pairs;
  Eigen::VectorXd bounds;
  const auto gap = [&](const Eigen::MatrixXd& at) {
    double least = std::numeric_limits<double>::infinity();
    for (int v = 3; v < 6; ++v)
      least = std::min(least, vertex_triangle_distance(at, v, Eigen::Vector3i(0, 1, 2)));
    for (int v = 0; v < 3; ++v)
      least = std::min(least, vertex_triangle_distance(at, v, Eigen::Vector3i(3, 4, 5)));
    for (int e = 0; e < 3; ++e) {
      for (int f = 0; f < 3; ++f)
        least = std::min(least, edge_edge_distance(at, e, (e + 1) % 3, 3 + f, 3 + (f + 1) % 3));
    }
    return least;
  };
  double floor = 0.0;
  for (int epoch = 0; epoch < 200; ++epoch) {
    proximity.find(surface, rest, x, reach, 0.01, pairs, bounds);
    floor = proximity.floor();
    Eigen::MatrixXd p = x;
    p.col(2).tail(3).array() -= 0.01;
    wobble::clamp_to_bounds(x, Eigen::Vector3d::Zero(), bounds, p);
    x = p;
    ASSERT_GE(gap(x), 0.9 * floor) << "epoch " << epoch;
    ASSERT_EQ(wobble::testing::count_mesh_crossings(x, F), 0) << "epoch " << epoch;
  }
  EXPECT_GT(floor, 0.0);
  EXPECT_LT(gap(x), 2.0 * floor) << "it should have been pressed down to the floor";
}

// Its bounds keep every pair apart, so the caller may skip its crossing guard, except where a
// found pair is closer than the floor (there rounding may decide), or a query stopped.
TEST(SelfContactProximity, SaysWhetherItsBoundsKeepEveryPairApart) {
  for (const double height : {0.004, 1e-6, 1e-12}) {
    Mesh mesh;
    mesh.add_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    add_probe(mesh, {0.2, 0.3, height});
    const Found found(mesh, constant_reach(mesh, 0.01), 0.005);
    ASSERT_GT(found.floor, 1e-12);
    ASSERT_LT(found.floor, 1e-6);
    EXPECT_EQ(found.covers, height > found.floor) << height;
    if (height < found.floor) {
      EXPECT_EQ(found.bounds(3), 0.0);
    }
  }
}

TEST(SelfContactProximity, ClampLeavesFreeVerticesAndSanitizesBounds) {
  const Eigen::MatrixXd x = Eigen::MatrixXd::Zero(3, 3);
  Eigen::MatrixXd p = Eigen::MatrixXd::Ones(3, 3);
  const Eigen::VectorXd bounds =
      (Eigen::VectorXd(3) << std::numeric_limits<double>::infinity(), -1.0, std::nan(""))
          .finished();
  EXPECT_EQ(wobble::clamp_to_bounds(x, Eigen::Vector3d(1, 1, 0), bounds, p), 2);
  EXPECT_EQ(p.row(0), Eigen::RowVector3d(1, 1, 1));  // no bound: untouched
  EXPECT_EQ(p.row(1), Eigen::RowVector3d(1, 1, 0));  // a bound of 0: the common motion alone
  EXPECT_EQ(p.row(2), Eigen::RowVector3d(1, 1, 0));
}

}  // namespace

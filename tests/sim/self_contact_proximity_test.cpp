// Self-contact proximity: the pairs closer than the contact distance, and the bounds on each
// vertex's motion that keep the surface from passing through itself.
#include "sim/contact/self_contact_proximity.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <tuple>
#include <vector>

#include "mesh_crossings.h"
#include "sim/contact/closest_points.h"
#include "sim/contact/vertex_row.h"

namespace {

using wobble::SelfContactPair;
using wobble::SelfContactProximity;
using wobble::vertex_row;
constexpr double gamma_ = SelfContactProximity::bound_fraction;

struct Mesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;
  // An n×n grid of spacing h in a plane z = const, from `origin`, two triangles a cell.
  void add_grid(int n, double h, const Eigen::Vector3d& origin) {
    const int first = static_cast<int>(vertices.size());
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j)
        vertices.push_back(origin + Eigen::Vector3d(j * h, i * h, 0.0));
    }
    for (int i = 0; i + 1 < n; ++i) {
      for (int j = 0; j + 1 < n; ++j) {
        const int a = first + i * n + j;
        triangles.emplace_back(a, a + 1, a + n + 1);
        triangles.emplace_back(a, a + n + 1, a + n);
      }
    }
  }
  void add_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    const int first = static_cast<int>(vertices.size());
    vertices.insert(vertices.end(), {a, b, c});
    triangles.emplace_back(first, first + 1, first + 2);
  }
  Eigen::MatrixXd x() const {
    Eigen::MatrixXd V(vertices.size(), 3);
    for (std::size_t i = 0; i < vertices.size(); ++i)
      V.row(i) = vertices[i].transpose();
    return V;
  }
  wobble::SpringNetwork network() const {
    wobble::SpringNetwork network;
    network.V = x();
    network.F.resize(triangles.size(), 3);
    for (std::size_t t = 0; t < triangles.size(); ++t)
      network.F.row(t) = triangles[t].transpose();
    network.m = Eigen::VectorXd::Ones(network.V.rows());
    return network;
  }
};

// A mesh's surface, its rest neighbours within `rest_reach` of its own positions (0: none), and
// find()'s answer at those positions.
struct Found {
  wobble::SelfCollisionSurface surface;
  wobble::RestNeighbours rest;
  Eigen::MatrixXd x;
  std::vector<SelfContactPair> pairs;
  Eigen::VectorXd bounds;
  Found(const Mesh& mesh, const Eigen::VectorXd& reach, double contact_distance,
        double rest_reach = 0.0, wobble::WorkerPool* pool = nullptr)
      : surface(mesh.network()), x(mesh.x()) {
    rest.find(surface, rest_reach);
    SelfContactProximity proximity(pool);
    proximity.find(surface, rest, x, reach, contact_distance, pairs, bounds);
  }
};

Eigen::VectorXd constant_reach(const Mesh& mesh, double r) {
  return Eigen::VectorXd::Constant(mesh.vertices.size(), r);
}

double vertex_triangle_distance(const Eigen::MatrixXd& x, int v, const Eigen::Vector3i& t) {
  const Eigen::Vector3d p = vertex_row(x, v), a = vertex_row(x, t(0)), b = vertex_row(x, t(1)),
                        c = vertex_row(x, t(2));
  const Eigen::Vector3d alpha = wobble::closest_on_triangle(p, a, b, c);
  return (p - alpha(0) * a - alpha(1) * b - alpha(2) * c).norm();
}

double edge_edge_distance(const Eigen::MatrixXd& x, int p0, int p1, int q0, int q1) {
  const Eigen::Vector3d x0 = vertex_row(x, p0), x1 = vertex_row(x, p1), y0 = vertex_row(x, q0),
                        y1 = vertex_row(x, q1);
  const Eigen::Vector2d su = wobble::closest_on_segments(x0, x1, y0, y1);
  return ((1.0 - su(0)) * x0 + su(0) * x1 - (1.0 - su(1)) * y0 - su(1) * y1).norm();
}

bool share_vertex(const SelfContactPair& pair) {
  const int first = pair.vertex_triangle ? 1 : 2;
  for (int i = 0; i < first; ++i) {
    for (int j = first; j < 4; ++j) {
      if (pair.vertex[i] == pair.vertex[j]) return true;
    }
  }
  return false;
}

// A probe triangle whose corner `tip` points down at the rest, its other corners far above.
void add_probe(Mesh& mesh, const Eigen::Vector3d& tip) {
  mesh.add_triangle(tip, tip + Eigen::Vector3d(0.1, 0.0, 0.5),
                    tip + Eigen::Vector3d(0.0, 0.1, 0.5));
}

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
    EXPECT_NEAR(found->bounds(3), gamma_ * 0.002, 1e-15);  // half the 4 mm, not the 1 cm reach
    EXPECT_NEAR(found->bounds(0), gamma_ * 0.002, 1e-15);  // a corner of the triangle below
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
    EXPECT_NEAR(found.bounds(v), gamma_ * reach(v), 1e-15) << v;
  EXPECT_EQ(found.bounds(6), std::numeric_limits<double>::infinity());
}

// Two jittered parallel 6×6 grids a few mm apart with random reaches: every pair that shares no
// vertex (rest neighbours within each grid included) stays apart however each vertex moves within
// its bound, and the bounds are the formula's, by brute force.
TEST(SelfContactProximity, BoundsKeepEveryPairApart) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> jitter(-0.001, 0.001), reach_of(0.0, 0.012);
  for (int trial = 0; trial < 5; ++trial) {
    Mesh mesh;
    mesh.add_grid(6, 0.01, Eigen::Vector3d::Zero());
    mesh.add_grid(6, 0.01, Eigen::Vector3d(0.003, 0.004, 0.004));
    for (Eigen::Vector3d& v : mesh.vertices)
      v += Eigen::Vector3d(jitter(random), jitter(random), jitter(random));
    Eigen::VectorXd reach(mesh.vertices.size());
    for (Eigen::Index v = 0; v < reach.size(); ++v)
      reach(v) = v % 7 == 0 ? 0.0 : reach_of(random);
    const Found found(mesh, reach, 0.004, 0.015);
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
    EXPECT_GT(pairs, 1000) << "the reaches should find many pairs";
    // The same distances by the same formulas: equal to rounding.
    for (int v = 0; v < found.x.rows(); ++v)
      EXPECT_NEAR(b(v), 0.5 * gamma_ * nearest(v), 1e-15) << v;
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

// An accordion of rows × rows vertices: panels 2 mm apart, each 4 cm tall, jittered.
Mesh accordion(int rows, unsigned seed) {
  Mesh mesh;
  mesh.add_grid(rows, 0.01, Eigen::Vector3d::Zero());
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-0.0005, 0.0005);
  for (int v = 0; v < static_cast<int>(mesh.vertices.size()); ++v) {
    const int i = v / rows, j = v % rows;
    mesh.vertices[v] = Eigen::Vector3d(0.002 * j + jitter(random), 0.01 * i + jitter(random),
                                       (j % 2 ? 0.02 : -0.02) + jitter(random));
  }
  return mesh;
}

bool same(const std::vector<SelfContactPair>& a, const std::vector<SelfContactPair>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a[k].vertex_triangle != b[k].vertex_triangle || a[k].depth != b[k].depth ||
        a[k].normal != b[k].normal)
      return false;
    for (int i = 0; i < 4; ++i) {
      if (a[k].vertex[i] != b[k].vertex[i] || a[k].beta[i] != b[k].beta[i]) return false;
    }
  }
  return true;
}

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

// A 60×60 grid with every vertex at one point: every query meets hundreds of features, stops,
// and freezes them; the pairs stay at most 32 a feature and the buffers O(features).
TEST(SelfContactProximity, ACoincidentGridIsBoundedAndFrozen) {
  Mesh mesh;
  mesh.add_grid(60, 0.01, Eigen::Vector3d::Zero());
  for (Eigen::Vector3d& v : mesh.vertices)
    v = Eigen::Vector3d(0.1, 0.2, 0.3);
  const wobble::SelfCollisionSurface surface(mesh.network());
  wobble::RestNeighbours rest;
  rest.find(surface, 0.0);
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

// A probe 3 mm above a stack of 600 coincident triangles: its query stops before it has seen
// them all, so it is frozen (b = 0) rather than trusted with half of 3 mm; far away, a triangle
// keeps its reach.
TEST(SelfContactProximity, AQueryThatStopsFreezesItsNeighbourhood) {
  Mesh mesh;
  for (int k = 0; k < 600; ++k)
    mesh.add_triangle({0, 0, 0}, {0.01, 0, 0}, {0, 0.01, 0});
  add_probe(mesh, {0.002, 0.002, 0.003});
  mesh.add_triangle({1, 1, 1}, {1.01, 1, 1}, {1, 1.01, 1});
  const Found found(mesh, constant_reach(mesh, 0.01), 0.005);
  EXPECT_EQ(found.bounds(1800), 0.0);
  for (int v = 1803; v < 1806; ++v)
    EXPECT_NEAR(found.bounds(v), gamma_ * 0.01, 1e-15);
  // With fewer than max_met triangles below, the probe is trusted with half its distance.
  Mesh few;
  for (int k = 0; k < 100; ++k)
    few.add_triangle({0, 0, 0}, {0.01, 0, 0}, {0, 0.01, 0});
  add_probe(few, {0.002, 0.002, 0.003});
  EXPECT_NEAR(Found(few, constant_reach(few, 0.01), 0.005).bounds(300), gamma_ * 0.0015, 1e-15);
}

}  // namespace

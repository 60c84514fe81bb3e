// The colliders' geometry: the signed distance and normal of collider_surface checked against
// brute force over points sampled on each surface, and the validation of their numbers.
#include "sim/contact/collider.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "sim/input_error.h"
#include "test_colliders.h"

namespace {

using wobble::Collider;
using wobble::ColliderType;

Collider sphere() {
  return wobble::testing::sphere_collider(Eigen::Vector3d(0.2, 0.5, -0.1), 0.3);
}

Collider box() {
  return wobble::testing::box_collider(Eigen::Vector3d(0.1, 0.4, 0.0),
                                       Eigen::Vector3d(1.2, 0.8, 0.6));
}

Collider capsule() {
  return wobble::testing::capsule_collider(Eigen::Vector3d(0.0, 0.0, 0.0),
                                           Eigen::Vector3d(0.3, 1.0, 0.2), 0.15);
}

// Points spread over a collider's surface, about `spacing` apart, written from its definition.
std::vector<Eigen::Vector3d> surface_samples(const Collider& c, double spacing) {
  std::vector<Eigen::Vector3d> points;
  auto add_ball = [&](const Eigen::Vector3d& center, double radius) {
    const int n = static_cast<int>(4.0 * M_PI * radius * radius / (spacing * spacing)) + 50;
    for (int i = 0; i < n; ++i) {  // a Fibonacci sphere
      const double y = 1.0 - 2.0 * (i + 0.5) / n, ring = std::sqrt(1.0 - y * y);
      const double angle = i * 2.399963229728653;
      points.push_back(center +
                       radius * Eigen::Vector3d(ring * std::cos(angle), y, ring * std::sin(angle)));
    }
  };
  switch (c.type) {
    case ColliderType::sphere:
      add_ball(c.center, c.radius);
      break;
    case ColliderType::box: {
      const Eigen::Vector3d low = c.center - 0.5 * c.size;
      const int n = static_cast<int>(c.size.maxCoeff() / spacing) + 1;
      for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
          for (int a = 0; a <= n; ++a) {
            for (int b = 0; b <= n; ++b) {
              Eigen::Vector3d p = low;
              p(axis) += side * c.size(axis);
              p((axis + 1) % 3) += c.size((axis + 1) % 3) * a / n;
              p((axis + 2) % 3) += c.size((axis + 2) % 3) * b / n;
              points.push_back(p);
            }
          }
        }
      }
      break;
    }
    case ColliderType::capsule: {
      // The two end balls, keeping their outer halves, and rings around the axis between them.
      const Eigen::Vector3d axis = c.to - c.from;
      add_ball(c.from, c.radius);
      add_ball(c.to, c.radius);
      std::vector<Eigen::Vector3d> caps;
      for (const Eigen::Vector3d& q : points) {
        const double t = (q - c.from).dot(axis) / axis.squaredNorm();
        if (t <= 0.0 || t >= 1.0) caps.push_back(q);
      }
      points.swap(caps);
      const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.normalized().cross(u);
      const int along = static_cast<int>(axis.norm() / spacing) + 1;
      const int around = static_cast<int>(2.0 * M_PI * c.radius / spacing) + 1;
      for (int i = 0; i <= along; ++i) {
        for (int j = 0; j < around; ++j) {
          const double angle = 2.0 * M_PI * j / around;
          points.push_back(c.from + axis * i / along +
                           c.radius * (std::cos(angle) * u + std::sin(angle) * v));
        }
      }
      break;
    }
    default:
      break;
  }
  return points;
}

// Whether a point is inside, from the definition.
bool inside(const Collider& c, const Eigen::Vector3d& p) {
  switch (c.type) {
    case ColliderType::sphere:
      return (p - c.center).norm() < c.radius;
    case ColliderType::box:
      return ((p - c.center).cwiseAbs() - 0.5 * c.size).maxCoeff() < 0.0;
    case ColliderType::capsule: {
      const Eigen::Vector3d axis = c.to - c.from;
      const double t = std::clamp((p - c.from).dot(axis) / axis.squaredNorm(), 0.0, 1.0);
      return (p - c.from - t * axis).norm() < c.radius;
    }
    default:
      return false;
  }
}

TEST(Collider, SignedDistanceAndNormalMatchBruteForce) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.5);
  for (const Collider& c : {sphere(), box(), capsule()}) {
    SCOPED_TRACE(wobble::collider_type_name(c.type));
    const double spacing = 0.01;
    const std::vector<Eigen::Vector3d> samples = surface_samples(c, spacing);
    int inside_count = 0;
    for (int trial = 0; trial < 400; ++trial) {
      // Every other point near the collider, so that some are inside even a thin one.
      const Eigen::Vector3d near =
          wobble::collider_anchor(c) +
          0.4 * Eigen::Vector3d(coordinate(random), coordinate(random), coordinate(random));
      const Eigen::Vector3d p =
          trial % 2 ? near
                    : Eigen::Vector3d(coordinate(random), coordinate(random), coordinate(random));
      const wobble::ColliderSurface surface = wobble::collider_surface(c, p);
      double nearest = 1e30;
      for (const Eigen::Vector3d& q : samples)
        nearest = std::min(nearest, (p - q).norm());
      // The samples are `spacing` apart: the true distance is within that of the nearest one.
      EXPECT_NEAR(std::abs(surface.distance), nearest, spacing) << p.transpose();
      EXPECT_EQ(surface.distance < 0.0, inside(c, p)) << p.transpose();
      EXPECT_NEAR(surface.normal.norm(), 1.0, 1e-12);
      // Stepping back along the normal by the distance lands on the surface.
      const Eigen::Vector3d foot = p - surface.distance * surface.normal;
      EXPECT_NEAR(wobble::collider_surface(c, foot).distance, 0.0, 1e-9) << p.transpose();
      inside_count += surface.distance < 0.0;
    }
    EXPECT_GT(inside_count, 5) << "the trials must test points inside too";
  }
}

TEST(Collider, GroundAndPlaneAreHalfSpaces) {
  Collider ground;
  ground.height = 0.25;
  EXPECT_DOUBLE_EQ(wobble::collider_surface(ground, Eigen::Vector3d(3, 0.1, -2)).distance, -0.15);
  Collider plane;
  plane.type = ColliderType::plane;
  plane.center = Eigen::Vector3d(0, 1, 0);
  plane.normal = Eigen::Vector3d(1, 1, 0);
  wobble::validate_collider(plane, "collider 0");
  EXPECT_NEAR(plane.normal.norm(), 1.0, 1e-15);
  const wobble::ColliderSurface s = wobble::collider_surface(plane, Eigen::Vector3d(1, 1, 5));
  EXPECT_NEAR(s.distance, std::sqrt(0.5), 1e-15);
  EXPECT_EQ(wobble::collider_scale(plane), std::numeric_limits<double>::infinity());
}

TEST(Collider, TranslateMovesEveryKindRigidly) {
  const Eigen::Vector3d offset(0.1, -0.2, 0.3);
  for (Collider c : {sphere(), box(), capsule()}) {
    const Eigen::Vector3d probe(0.9, 0.8, 0.7);
    const double before = wobble::collider_surface(c, probe).distance;
    wobble::translate_collider(c, offset);
    EXPECT_NEAR(wobble::collider_surface(c, probe + offset).distance, before, 1e-12);
  }
}

TEST(Collider, ValidationNamesTheColliderAndTheField) {
  Collider bad = sphere();
  bad.radius = -1.0;
  try {
    wobble::validate_collider(bad, "collider 3");
    FAIL() << "a negative radius must be refused";
  } catch (const wobble::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("collider 3 radius"), std::string::npos)
        << error.what();
  }
  Collider flat;
  flat.type = ColliderType::plane;
  flat.normal = Eigen::Vector3d::Zero();
  EXPECT_THROW(wobble::validate_collider(flat, "collider 0"), wobble::InputError);
  Collider sticky = box();
  sticky.friction = std::nan("");
  EXPECT_THROW(wobble::validate_collider(sticky, "collider 0"), wobble::InputError);
  Collider huge = box();
  huge.size = Eigen::Vector3d(1, 1e9, 1);
  EXPECT_THROW(wobble::validate_collider(huge, "collider 0"), wobble::InputError);
}

}  // namespace

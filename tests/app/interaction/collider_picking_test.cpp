#include "app/interaction/collider_picking.h"

#include <gtest/gtest.h>

#include "../../sim/test_colliders.h"

namespace {

using wobble::Collider;
using wobble::ColliderType;
using wobble::Ray;
using wobble::testing::sphere_collider;

Ray ray(const Eigen::Vector3f& origin, const Eigen::Vector3f& direction) {
  return Ray{origin, direction.normalized()};
}

// Hit points are found to the marching tolerance (1e-5 m) plus float rounding.
constexpr float tolerance = 1e-4f;

TEST(ColliderPicking, RayMeetsTheFrontOfASphere) {
  const auto hit =
      wobble::pick_collider(ray({0, 0, 5}, {0, 0, -1}), {sphere_collider({0, 0, 0}, 1.0)});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->index, 0);
  EXPECT_NEAR(hit->distance, 4.0f, tolerance);
  EXPECT_TRUE(hit->point.isApprox(Eigen::Vector3f(0, 0, 1), tolerance));
  // Just past the silhouette there is nothing, and nothing behind the ray's origin.
  EXPECT_FALSE(
      wobble::pick_collider(ray({1.01f, 0, 5}, {0, 0, -1}), {sphere_collider({0, 0, 0}, 1.0)}));
  EXPECT_FALSE(wobble::pick_collider(ray({0, 0, 5}, {0, 0, 1}), {sphere_collider({0, 0, 0}, 1.0)}));
  // Just inside the silhouette it is still a hit.
  EXPECT_TRUE(
      wobble::pick_collider(ray({0.99f, 0, 5}, {0, 0, -1}), {sphere_collider({0, 0, 0}, 1.0)}));
}

TEST(ColliderPicking, TheNearestOfSeveralWins) {
  const std::vector<Collider> colliders = {sphere_collider({0, 0, -3}, 0.5),
                                           sphere_collider({0, 0, 0}, 0.5)};
  const auto hit = wobble::pick_collider(ray({0, 0, 5}, {0, 0, -1}), colliders);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->index, 1);
  EXPECT_NEAR(hit->distance, 4.5f, tolerance);
}

TEST(ColliderPicking, BoxFaceAndCapsuleSide) {
  Collider box;
  box.type = ColliderType::box;
  box.center = Eigen::Vector3d(0, 1, 0);
  box.size = Eigen::Vector3d(2, 1, 4);  // full edges: x from −1 to 1
  const auto on_box = wobble::pick_collider(ray({-5, 1.2f, 0.5f}, {1, 0, 0}), {box});
  ASSERT_TRUE(on_box);
  EXPECT_NEAR(on_box->point.x(), -1.0f, tolerance);
  EXPECT_FALSE(wobble::pick_collider(ray({-5, 1.6f, 0.5f}, {1, 0, 0}), {box}));  // above its top

  Collider capsule;
  capsule.type = ColliderType::capsule;
  capsule.from = Eigen::Vector3d(-2, 0, 0);
  capsule.to = Eigen::Vector3d(2, 0, 0);
  capsule.radius = 0.3;
  // From above onto the cylinder, and from the side onto an end cap.
  const auto side = wobble::pick_collider(ray({1, 3, 0}, {0, -1, 0}), {capsule});
  ASSERT_TRUE(side);
  EXPECT_NEAR(side->point.y(), 0.3f, tolerance);
  const auto cap = wobble::pick_collider(ray({5, 0, 0}, {-1, 0, 0}), {capsule});
  ASSERT_TRUE(cap);
  EXPECT_NEAR(cap->point.x(), 2.3f, tolerance);
}

TEST(ColliderPicking, GroundAndPlanesAreNeverPicked) {
  Collider ground, plane;
  plane.type = ColliderType::plane;
  plane.normal = Eigen::Vector3d(0, 1, 0);
  EXPECT_FALSE(wobble::pick_collider(ray({0, 5, 0}, {0, -1, 0}), {ground, plane}));
  // A sphere behind them still is, with its own index.
  const auto hit = wobble::pick_collider(ray({0, 5, 0}, {0, -1, 0}),
                                         {ground, plane, sphere_collider({0, 1, 0}, 0.5)});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->index, 2);
}

}  // namespace

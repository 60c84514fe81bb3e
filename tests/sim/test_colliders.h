#ifndef WOBBLE_TESTS_SIM_TEST_COLLIDERS_H
#define WOBBLE_TESTS_SIM_TEST_COLLIDERS_H

#include <Eigen/Core>

#include "sim/contact/collider.h"

namespace wobble::testing {

// Colliders as the tests place them (m).
inline Collider ground_collider(double height = 0.0) {
  Collider c;
  c.type = ColliderType::ground;
  c.height = height;
  return c;
}

inline Collider sphere_collider(const Eigen::Vector3d& center, double radius) {
  Collider c;
  c.type = ColliderType::sphere;
  c.center = center;
  c.radius = radius;
  return c;
}

// Axis-aligned, `size` its full edge lengths.
inline Collider box_collider(const Eigen::Vector3d& center, const Eigen::Vector3d& size) {
  Collider c;
  c.type = ColliderType::box;
  c.center = center;
  c.size = size;
  return c;
}

inline Collider capsule_collider(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                 double radius) {
  Collider c;
  c.type = ColliderType::capsule;
  c.from = from;
  c.to = to;
  c.radius = radius;
  return c;
}

}  // namespace wobble::testing

#endif

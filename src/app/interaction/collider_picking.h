#ifndef WOBBLE_APP_INTERACTION_COLLIDER_PICKING_H
#define WOBBLE_APP_INTERACTION_COLLIDER_PICKING_H

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "app/interaction/picking.h"
#include "sim/contact/collider.h"

namespace wobble {

// Where a cursor ray first meets a collider that can be grabbed.
struct ColliderHit {
  int index = -1;                                   // into the colliders
  float distance = 0.0f;                            // along the ray from its origin (m)
  Eigen::Vector3f point = Eigen::Vector3f::Zero();  // on the collider's surface (m)
};

// The nearest sphere, box or capsule the ray meets in front of its origin, within
// `max_distance` (m); nothing if it meets none. The ground and planes are never picked: they
// have no place to be dragged from. Marches along the ray by the collider's signed distance
// (collider_surface), so what is picked is exactly the solid that contact uses. A ray that
// starts inside a collider meets it at its origin.
std::optional<ColliderHit> pick_collider(const Ray& ray, const std::vector<Collider>& colliders,
                                         float max_distance = 1e4f);

}  // namespace wobble

#endif

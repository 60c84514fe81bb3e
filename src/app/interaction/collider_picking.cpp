#include "app/interaction/collider_picking.h"

#include <algorithm>

namespace wobble {

namespace {

bool grabbable(const Collider& collider) {
  return collider.type == ColliderType::sphere || collider.type == ColliderType::box ||
         collider.type == ColliderType::capsule;
}

// Sphere tracing: the signed distance is never more than the distance to the surface along any
// direction, so a step of that length cannot pass through the solid. A ray grazing the surface
// creeps along it; after the step budget it counts as a miss, which on screen is a pixel's
// width at the silhouette.
std::optional<double> march(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                            const Collider& collider, double max_distance) {
  const double tolerance = 1e-5 * std::max(1.0, collider_scale(collider));
  double t = 0.0;
  for (int step = 0; step < 512 && t <= max_distance; ++step) {
    const double distance = collider_surface(collider, origin + t * direction).distance;
    if (distance < tolerance) return t;
    t += distance;
  }
  return std::nullopt;
}

}  // namespace

std::optional<ColliderHit> pick_collider(const Ray& ray, const std::vector<Collider>& colliders,
                                         float max_distance) {
  const Eigen::Vector3d origin = ray.origin.cast<double>();
  const Eigen::Vector3d direction = ray.direction.cast<double>().normalized();
  std::optional<ColliderHit> nearest;
  for (int i = 0; i < static_cast<int>(colliders.size()); ++i) {
    if (!grabbable(colliders[i])) continue;
    const std::optional<double> t = march(origin, direction, colliders[i], max_distance);
    if (!t || (nearest && *t >= nearest->distance)) continue;
    ColliderHit hit;
    hit.index = i;
    hit.distance = static_cast<float>(*t);
    hit.point = (origin + *t * direction).cast<float>();
    nearest = hit;
  }
  return nearest;
}

}  // namespace wobble

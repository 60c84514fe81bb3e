#ifndef WOBBLE_SIM_CONTACT_COLLIDER_H
#define WOBBLE_SIM_CONTACT_COLLIDER_H

#include <Eigen/Core>
#include <string>
#include <vector>

namespace wobble {

enum class ColliderType {
  ground,   // the plane y = height, solid below
  plane,    // through `center` with unit `normal`, solid on the side the normal points away from
  sphere,   // `center`, `radius`
  box,      // axis-aligned: `center`, full edge lengths `size`
  capsule,  // the points within `radius` of the segment `from`–`to`
};

// A fixed or hand-moved solid that vertices cannot enter. Only the fields of its type matter.
struct Collider {
  ColliderType type = ColliderType::ground;
  double height = 0.0;                                // ground (m)
  Eigen::Vector3d center = Eigen::Vector3d::Zero();   // plane (a point on it), sphere, box (m)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();  // plane; normalized when validated
  Eigen::Vector3d size = Eigen::Vector3d::Ones();     // box: edge lengths along x, y, z (m)
  Eigen::Vector3d from = Eigen::Vector3d::Zero();     // capsule (m)
  Eigen::Vector3d to = Eigen::Vector3d::UnitY();      // capsule (m)
  double radius = 0.5;                                // sphere, capsule (m)
  // Coulomb coefficient μ against this collider; negative: the material's (ContactParams).
  double friction = -1.0;
};

// "ground", "plane", "sphere", "box", "capsule".
const char* collider_type_name(ColliderType type);

// The surface point of a collider nearest to a point: the signed distance to it (m, negative
// inside) and the outward unit normal there. For a point exactly on a box edge or a capsule
// axis the normal is one of the valid ones, chosen deterministically.
struct ColliderSurface {
  double distance = 0.0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();
};
ColliderSurface collider_surface(const Collider& collider, const Eigen::Vector3d& point);

// The size a penetration is measured against: the radius of a sphere or capsule, the smallest
// half edge of a box, and infinity for the unbounded ground and plane.
double collider_scale(const Collider& collider);

// Moves a collider rigidly by `offset` (m): what dragging it with the mouse does.
void translate_collider(Collider& collider, const Eigen::Vector3d& offset);

// A point inside the collider (its centre; for the ground and a plane, the point of the surface
// under the origin): where a grab starts measuring from.
Eigen::Vector3d collider_anchor(const Collider& collider);

// Throws InputError unless the collider's numbers are finite and within sim/value_limits.h
// (sizes within limits::collider_size, positions within limits::coordinate, a plane normal not
// zero, friction negative or within limits::friction). `what` starts the message: "collider 2".
// Normalizes a plane's normal (one already of unit length up to 4 ulps is left as it is).
void validate_collider(Collider& collider, const std::string& what);

}  // namespace wobble

#endif

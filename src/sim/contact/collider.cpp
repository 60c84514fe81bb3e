#include "sim/contact/collider.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/input_error.h"
#include "sim/value_limits.h"

namespace wobble {

namespace {

ColliderSurface plane_surface(const Eigen::Vector3d& point_on_plane, const Eigen::Vector3d& normal,
                              const Eigen::Vector3d& point) {
  return {(point - point_on_plane).dot(normal), normal};
}

// Distance from a point to a ball around `center`; at the centre itself the normal is up, so the
// choice is the same on every run.
ColliderSurface ball_surface(const Eigen::Vector3d& center, double radius,
                             const Eigen::Vector3d& point) {
  const Eigen::Vector3d away = point - center;
  const double length = away.norm();
  if (length == 0.0) return {-radius, Eigen::Vector3d::UnitY()};
  return {length - radius, away / length};
}

ColliderSurface box_surface(const Collider& box, const Eigen::Vector3d& point) {
  const Eigen::Vector3d half = 0.5 * box.size;
  const Eigen::Vector3d local = point - box.center;
  const Eigen::Vector3d q = local.cwiseAbs() - half;  // > 0 along the axes where it is outside
  if (q.maxCoeff() > 0.0) {
    const Eigen::Vector3d outside = q.cwiseMax(0.0);
    const double distance = outside.norm();
    Eigen::Vector3d normal;
    for (int c = 0; c < 3; ++c)
      normal(c) = local(c) < 0.0 ? -outside(c) : outside(c);
    return {distance, normal / distance};
  }
  // Inside: out through the nearest face (the first axis on a tie).
  int axis = 0;
  for (int c = 1; c < 3; ++c) {
    if (q(c) > q(axis)) axis = c;
  }
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  normal(axis) = local(axis) < 0.0 ? -1.0 : 1.0;
  return {q(axis), normal};
}

ColliderSurface capsule_surface(const Collider& capsule, const Eigen::Vector3d& point) {
  const Eigen::Vector3d axis = capsule.to - capsule.from;
  const double length2 = axis.squaredNorm();
  double t = length2 > 0.0 ? (point - capsule.from).dot(axis) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const Eigen::Vector3d nearest = capsule.from + t * axis;
  ColliderSurface surface = ball_surface(nearest, capsule.radius, point);
  if ((point - nearest).squaredNorm() == 0.0 && length2 > 0.0) {
    // On the axis: any direction across it will do; take the one across the axis nearest +y.
    Eigen::Vector3d across = Eigen::Vector3d::UnitY() - axis * (axis.y() / length2);
    if (across.squaredNorm() < 1e-12)
      across = Eigen::Vector3d::UnitX() - axis * (axis.x() / length2);
    surface.normal = across.normalized();
  }
  return surface;
}

void check_vector(const Eigen::Vector3d& value, const ValueRange& range, const std::string& what) {
  const std::string problem = outside_limits(value.array(), range, what);
  if (!problem.empty()) throw InputError(problem);
}

void check_number(double value, const ValueRange& range, const std::string& what) {
  if (!range.contains(value)) {
    throw InputError(what + ": expected " + expected_in(range) + ", got " + limit_text(value));
  }
}

}  // namespace

const char* collider_type_name(ColliderType type) {
  switch (type) {
    case ColliderType::ground:
      return "ground";
    case ColliderType::plane:
      return "plane";
    case ColliderType::sphere:
      return "sphere";
    case ColliderType::box:
      return "box";
    case ColliderType::capsule:
      return "capsule";
  }
  return "collider";
}

ColliderSurface collider_surface(const Collider& collider, const Eigen::Vector3d& point) {
  switch (collider.type) {
    case ColliderType::ground:
      return {point.y() - collider.height, Eigen::Vector3d::UnitY()};
    case ColliderType::plane:
      return plane_surface(collider.center, collider.normal, point);
    case ColliderType::sphere:
      return ball_surface(collider.center, collider.radius, point);
    case ColliderType::box:
      return box_surface(collider, point);
    case ColliderType::capsule:
      return capsule_surface(collider, point);
  }
  return {};
}

double collider_scale(const Collider& collider) {
  switch (collider.type) {
    case ColliderType::sphere:
    case ColliderType::capsule:
      return collider.radius;
    case ColliderType::box:
      return 0.5 * collider.size.minCoeff();
    case ColliderType::ground:
    case ColliderType::plane:
      break;
  }
  return std::numeric_limits<double>::infinity();
}

void translate_collider(Collider& collider, const Eigen::Vector3d& offset) {
  collider.height += offset.y();
  collider.center += offset;
  collider.from += offset;
  collider.to += offset;
}

Eigen::Vector3d collider_anchor(const Collider& collider) {
  switch (collider.type) {
    case ColliderType::ground:
      return Eigen::Vector3d(0.0, collider.height, 0.0);
    case ColliderType::capsule:
      return 0.5 * (collider.from + collider.to);
    case ColliderType::plane:
    case ColliderType::sphere:
    case ColliderType::box:
      break;
  }
  return collider.center;
}

void validate_collider(Collider& collider, const std::string& what) {
  if (collider.friction >= 0.0 || std::isnan(collider.friction)) {
    check_number(collider.friction, limits::friction, what + " friction");
  }
  switch (collider.type) {
    case ColliderType::ground:
      check_number(collider.height, limits::coordinate, what + " height");
      return;
    case ColliderType::plane: {
      check_vector(collider.center, limits::coordinate, what + " point");
      check_vector(collider.normal, limits::coordinate, what + " normal");
      const double length = collider.normal.norm();
      if (!(length > 1e-12)) throw InputError(what + " normal: expected a non-zero vector");
      // A normal that is already unit up to rounding is kept as it is: dividing it again moves
      // about a third of them by an ulp, so a saved scene's plane would not read back bit for bit.
      if (std::abs(length - 1.0) > 4.0 * std::numeric_limits<double>::epsilon()) {
        collider.normal /= length;
      }
      return;
    }
    case ColliderType::sphere:
      check_vector(collider.center, limits::coordinate, what + " center");
      check_number(collider.radius, limits::collider_size, what + " radius");
      return;
    case ColliderType::box:
      check_vector(collider.center, limits::coordinate, what + " center");
      check_vector(collider.size, limits::collider_size, what + " size");
      return;
    case ColliderType::capsule:
      check_vector(collider.from, limits::coordinate, what + " from");
      check_vector(collider.to, limits::coordinate, what + " to");
      check_number(collider.radius, limits::collider_size, what + " radius");
      return;
  }
}

}  // namespace wobble

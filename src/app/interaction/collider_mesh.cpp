#include "app/interaction/collider_mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace wobble {

namespace {

constexpr float pi_float = 3.14159265358979f;

// Two unit vectors u, v with u × v = axis (unit), so that (u, v, axis) is right-handed.
void perpendicular_frame(const Eigen::Vector3f& axis, Eigen::Vector3f& u, Eigen::Vector3f& v) {
  const Eigen::Vector3f helper =
      std::abs(axis.x()) < 0.9f ? Eigen::Vector3f::UnitX() : Eigen::Vector3f::UnitY();
  u = axis.cross(helper).normalized();
  v = axis.cross(u);
}

void add_vertex(ColliderTriangles& mesh, const Eigen::Vector3f& position,
                const Eigen::Vector3f& normal) {
  mesh.positions.insert(mesh.positions.end(), {position.x(), position.y(), position.z()});
  mesh.normals.insert(mesh.normals.end(), {normal.x(), normal.y(), normal.z()});
}

// A quad a, b, c, d counter-clockwise from outside, as two triangles.
void add_quad(ColliderTriangles& mesh, unsigned a, unsigned b, unsigned c, unsigned d) {
  mesh.triangles.insert(mesh.triangles.end(), {a, b, c, a, c, d});
}

// The points within `radius` of the segment from–to: latitude rings from the pole below `from`
// to the pole above `to`, the equator twice (once around each end), so the band between the two
// equators is the cylinder.
void add_swept_sphere(const Eigen::Vector3f& from, const Eigen::Vector3f& to, float radius,
                      int segments, ColliderTriangles& mesh) {
  const Eigen::Vector3f along = to - from;
  const Eigen::Vector3f axis =
      along.norm() > 0.0f ? Eigen::Vector3f(along.normalized()) : Eigen::Vector3f::UnitY();
  Eigen::Vector3f u, v;
  perpendicular_frame(axis, u, v);
  const int around = std::max(segments, 3);
  const int per_half = std::max(segments / 4, 2);  // rings from a pole to the equator
  const unsigned first = static_cast<unsigned>(mesh.vertex_count());
  int rings = 0;
  for (int end = 0; end < 2; ++end) {
    const Eigen::Vector3f& center = end == 0 ? from : to;
    for (int r = 0; r <= per_half; ++r) {
      // Latitude from −90° to 0° around `from`, then 0° to 90° around `to`.
      const float latitude =
          (end == 0 ? -1.0f + float(r) / per_half : float(r) / per_half) * 0.5f * pi_float;
      for (int j = 0; j < around; ++j) {
        const float longitude = 2.0f * pi_float * j / around;
        // The poles exactly on the axis, so their triangles collapse cleanly instead of
        // turning by a rounding error.
        const bool pole = (end == 0 && r == 0) || (end == 1 && r == per_half);
        const float across = pole ? 0.0f : std::cos(latitude);
        const float up = pole ? (end == 0 ? -1.0f : 1.0f) : std::sin(latitude);
        const Eigen::Vector3f normal =
            across * (std::cos(longitude) * u + std::sin(longitude) * v) + up * axis;
        add_vertex(mesh, center + radius * normal, normal);
      }
      ++rings;
    }
  }
  for (int r = 0; r + 1 < rings; ++r) {
    for (int j = 0; j < around; ++j) {
      const unsigned a = first + r * around + j;
      const unsigned b = first + r * around + (j + 1) % around;
      add_quad(mesh, a, b, b + around, a + around);
    }
  }
}

void add_box(const Eigen::Vector3f& center, const Eigen::Vector3f& size, ColliderTriangles& mesh) {
  const Eigen::Vector3f half = 0.5f * size;
  for (int axis = 0; axis < 3; ++axis) {
    for (float side : {1.0f, -1.0f}) {
      Eigen::Vector3f normal = Eigen::Vector3f::Zero();
      normal(axis) = side;
      // t1 × t2 = the outward normal, so (−,−), (+,−), (+,+), (−,+) runs counter-clockwise.
      const Eigen::Vector3f t1 = Eigen::Vector3f::Unit((axis + 1) % 3);
      const Eigen::Vector3f t2 = side * Eigen::Vector3f::Unit((axis + 2) % 3);
      const unsigned first = static_cast<unsigned>(mesh.vertex_count());
      for (const auto& [a, b] :
           {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}}) {
        add_vertex(mesh, center + half.cwiseProduct(normal + a * t1 + b * t2), normal);
      }
      add_quad(mesh, first, first + 1, first + 2, first + 3);
    }
  }
}

void add_plane_square(const Eigen::Vector3f& point, const Eigen::Vector3f& plane_normal,
                      const Eigen::Vector3f& focus, float half_extent, ColliderTriangles& mesh) {
  const Eigen::Vector3f normal = plane_normal.normalized();
  const Eigen::Vector3f center = focus - (focus - point).dot(normal) * normal;
  Eigen::Vector3f u, v;
  perpendicular_frame(normal, u, v);
  const unsigned first = static_cast<unsigned>(mesh.vertex_count());
  for (const auto& [a, b] : {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}})
    add_vertex(mesh, center + half_extent * (a * u + b * v), normal);
  add_quad(mesh, first, first + 1, first + 2, first + 3);
}

}  // namespace

void append_collider_triangles(const Collider& collider, const Eigen::Vector3f& plane_focus,
                               float plane_half_extent, ColliderTriangles& mesh, int segments) {
  const Eigen::Vector3f center = collider.center.cast<float>();
  switch (collider.type) {
    case ColliderType::sphere:
      add_swept_sphere(center, center, static_cast<float>(collider.radius), segments, mesh);
      break;
    case ColliderType::capsule:
      add_swept_sphere(collider.from.cast<float>(), collider.to.cast<float>(),
                       static_cast<float>(collider.radius), segments, mesh);
      break;
    case ColliderType::box:
      add_box(center, collider.size.cast<float>(), mesh);
      break;
    case ColliderType::plane:
      add_plane_square(center, collider.normal.cast<float>(), plane_focus, plane_half_extent, mesh);
      break;
    case ColliderType::ground:
      break;
  }
}

ColliderTriangles collider_triangles(const std::vector<Collider>& colliders,
                                     const Eigen::Vector3f& plane_focus, float plane_half_extent) {
  ColliderTriangles mesh;
  for (const Collider& collider : colliders)
    append_collider_triangles(collider, plane_focus, plane_half_extent, mesh);
  return mesh;
}

}  // namespace wobble

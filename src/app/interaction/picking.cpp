#include "app/interaction/picking.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

namespace wobble {

std::optional<Eigen::Vector3f> project_to_window(const Eigen::Matrix4f& view_projection,
                                                 const Eigen::Vector3f& point,
                                                 const Eigen::Vector2f& viewport) {
  const Eigen::Vector4f clip = view_projection * point.homogeneous();
  if (!(clip.w() > 0.0f)) return std::nullopt;
  const Eigen::Vector2f ndc = clip.head<2>() / clip.w();
  // y flips: normalized device coordinates grow upwards, window coordinates downwards. The clip
  // w of a perspective projection is the depth in front of the eye.
  return Eigen::Vector3f(0.5f * (ndc.x() + 1.0f) * viewport.x(),
                         0.5f * (1.0f - ndc.y()) * viewport.y(), clip.w());
}

int pick_vertex(const Eigen::Matrix4f& view_projection, const float* positions, int vertex_count,
                const unsigned char* eligible, const Eigen::Vector2f& cursor,
                const Eigen::Vector2f& viewport, float radius) {
  // Two passes: the depth of the nearest candidate, then the candidate closest to the cursor
  // among those about as near. Nearest-first alone would pick a neighbour on an oblique sheet;
  // closest-to-cursor alone could pick a vertex on the far side of a solid.
  const auto candidate = [&](int i) -> std::optional<Eigen::Vector3f> {
    if (eligible != nullptr && eligible[i] == 0) return std::nullopt;
    const std::optional<Eigen::Vector3f> at = project_to_window(
        view_projection, Eigen::Map<const Eigen::Vector3f>(positions + 3 * i), viewport);
    if (!at || (at->head<2>() - cursor).squaredNorm() > radius * radius) return std::nullopt;
    return at;
  };
  float nearest_depth = std::numeric_limits<float>::infinity();
  for (int i = 0; i < vertex_count; ++i) {
    if (const auto at = candidate(i)) nearest_depth = std::min(nearest_depth, at->z());
  }
  const float front_layer = 1.05f * nearest_depth;
  int best = -1;
  float best_distance = std::numeric_limits<float>::infinity();
  for (int i = 0; i < vertex_count; ++i) {
    const auto at = candidate(i);
    if (!at || at->z() > front_layer) continue;
    const float distance = (at->head<2>() - cursor).squaredNorm();
    if (distance < best_distance) {
      best = i;
      best_distance = distance;
    }
  }
  return best;
}

Ray cursor_ray(const Eigen::Matrix4f& view, const Eigen::Matrix4f& projection,
               const Eigen::Vector2f& cursor, const Eigen::Vector2f& viewport) {
  const Eigen::Matrix4f inverse = (projection * view).inverse();
  const float x = 2.0f * cursor.x() / viewport.x() - 1.0f;
  const float y = 1.0f - 2.0f * cursor.y() / viewport.y();
  const Eigen::Vector4f near = inverse * Eigen::Vector4f(x, y, -1.0f, 1.0f);
  const Eigen::Vector4f far = inverse * Eigen::Vector4f(x, y, 1.0f, 1.0f);
  Ray ray;
  ray.origin = near.head<3>() / near.w();
  ray.direction = (far.head<3>() / far.w() - ray.origin).normalized();
  return ray;
}

std::optional<Eigen::Vector3f> intersect_plane(const Ray& ray, const Eigen::Vector3f& point,
                                               const Eigen::Vector3f& normal) {
  const float along = ray.direction.dot(normal);
  if (std::abs(along) < 1e-8f) return std::nullopt;
  const float t = (point - ray.origin).dot(normal) / along;
  if (!(t >= 0.0f)) return std::nullopt;
  return ray.origin + t * ray.direction;
}

}  // namespace wobble

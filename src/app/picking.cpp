#include "picking.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

namespace wobble {

std::optional<Eigen::Vector3f> project_to_window(const Eigen::Matrix4f& view_projection,
                                                 const Eigen::Vector3f& point,
                                                 const Eigen::Vector2f& viewport) {
  const Eigen::Vector4f clip = view_projection * point.homogeneous();
  if (!(clip.w() > 0.0f)) return std::nullopt;
  const Eigen::Vector3f ndc = clip.head<3>() / clip.w();
  // y flips: normalized device coordinates grow upwards, window coordinates downwards.
  return Eigen::Vector3f(0.5f * (ndc.x() + 1.0f) * viewport.x(),
                         0.5f * (1.0f - ndc.y()) * viewport.y(), ndc.z());
}

int pick_vertex(const Eigen::Matrix4f& view_projection, const float* positions, int vertex_count,
                const unsigned char* eligible, const Eigen::Vector2f& cursor,
                const Eigen::Vector2f& viewport, float radius) {
  int best = -1;
  float best_depth = 0.0f;
  for (int i = 0; i < vertex_count; ++i) {
    if (eligible != nullptr && eligible[i] == 0) continue;
    const std::optional<Eigen::Vector3f> at = project_to_window(
        view_projection, Eigen::Map<const Eigen::Vector3f>(positions + 3 * i), viewport);
    if (!at || (at->head<2>() - cursor).squaredNorm() > radius * radius) continue;
    if (best < 0 || at->z() < best_depth) {
      best = i;
      best_depth = at->z();
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

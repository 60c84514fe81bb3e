#ifndef WOBBLE_APP_INTERACTION_PICKING_H
#define WOBBLE_APP_INTERACTION_PICKING_H

#include <Eigen/Core>
#include <optional>

namespace wobble {

// Picking and dragging in screen space, without GL: no depth buffer is read, so a drag costs one
// pass over the vertices per frame. Window coordinates are pixels from the top-left corner;
// `viewport` is the window's (width, height) in those units.

// Where `point` lands in the window: (x, y, depth), depth being the distance in front of the eye
// along the view axis. Nothing for a point behind the eye.
std::optional<Eigen::Vector3f> project_to_window(const Eigen::Matrix4f& view_projection,
                                                 const Eigen::Vector3f& point,
                                                 const Eigen::Vector2f& viewport);

// The vertex under the cursor, or -1: of the vertices within `radius` pixels of `cursor`, those
// in the front layer (at most 5% deeper than the nearest one, so not one hidden behind a
// surface), and of these the one drawn closest to the cursor.
//   positions  #V by 3, row-major
//   eligible   #V flags (non-zero: may be picked), or null for every vertex
int pick_vertex(const Eigen::Matrix4f& view_projection, const float* positions, int vertex_count,
                const unsigned char* eligible, const Eigen::Vector2f& cursor,
                const Eigen::Vector2f& viewport, float radius);

// The ray from the eye through the cursor, in world space; direction has unit length.
struct Ray {
  Eigen::Vector3f origin;
  Eigen::Vector3f direction;
};
Ray cursor_ray(const Eigen::Matrix4f& view, const Eigen::Matrix4f& projection,
               const Eigen::Vector2f& cursor, const Eigen::Vector2f& viewport);

// Where `ray` meets the plane through `point` with normal `normal`; nothing if it runs parallel
// to the plane or meets it behind its origin.
std::optional<Eigen::Vector3f> intersect_plane(const Ray& ray, const Eigen::Vector3f& point,
                                               const Eigen::Vector3f& normal);

}  // namespace wobble

#endif

#ifndef WOBBLE_RENDER_CAMERA_H
#define WOBBLE_RENDER_CAMERA_H

#include <Eigen/Core>

namespace wobble {

// A camera orbiting a target point. Angles in radians, lengths in metres. y is up.
//   eye = target + distance · (cos(pitch) sin(yaw), sin(pitch), cos(pitch) cos(yaw))
// so yaw = 0, pitch = 0 looks from +z towards -z.
struct OrbitCamera {
  Eigen::Vector3f target = Eigen::Vector3f::Zero();
  float distance = 3.0f;
  float yaw = 0.0f;
  float pitch = 0.0f;
  float vertical_fov = 0.7854f;  // 45°

  static constexpr float max_pitch = 1.55f;  // just short of straight up or down
  static constexpr float min_distance = 1e-3f;
  static constexpr float max_distance = 1e4f;
};

Eigen::Vector3f camera_eye(const OrbitCamera& camera);
// Unit vector from the eye towards the target.
Eigen::Vector3f camera_forward(const OrbitCamera& camera);

// World to eye coordinates (right-handed, looking down -z), as OpenGL expects.
Eigen::Matrix4f view_matrix(const OrbitCamera& camera);
// Perspective projection for a viewport of width/height `aspect`. The near and far planes follow
// the distance, so zooming far in or out never clips the target.
Eigen::Matrix4f projection_matrix(const OrbitCamera& camera, float aspect);

// Mouse gestures, in window pixels. `viewport_height` makes them independent of window size.
// Orbit: a drag across the full height turns the camera by π.
void orbit_camera(OrbitCamera& camera, float dx_pixels, float dy_pixels, float viewport_height);
// Pan: the point under the cursor at the target's depth stays under the cursor.
void pan_camera(OrbitCamera& camera, float dx_pixels, float dy_pixels, float viewport_height);
// Zoom: each wheel step (positive = towards the target) divides the distance by 1.15.
void zoom_camera(OrbitCamera& camera, float wheel_steps);

// Aim at the centre of the box [lower, upper] and move back until its bounding sphere fits the
// viewport of width/height `aspect`, keeping the direction of view.
void frame_box(OrbitCamera& camera, const Eigen::Vector3f& lower, const Eigen::Vector3f& upper,
               float aspect);

}  // namespace wobble

#endif

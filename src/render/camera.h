#ifndef WOBBLE_RENDER_CAMERA_H
#define WOBBLE_RENDER_CAMERA_H

#include <Eigen/Core>
#include <limits>

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
  // Where the target appears, in normalized device coordinates (-1 to 1, y up); zero is the
  // centre. Framing moves it off centre to frame a shape into the part of the view a panel leaves
  // free, and orbiting and zooming then keep the shape there.
  Eigen::Vector2f lens_shift = Eigen::Vector2f::Zero();

  static constexpr float max_pitch = 1.55f;  // just short of straight up or down
  static constexpr float min_distance = 1e-3f;
  static constexpr float max_distance = 1e4f;
};

Eigen::Vector3f camera_eye(const OrbitCamera& camera);
// Unit vector from the eye towards the target.
Eigen::Vector3f camera_forward(const OrbitCamera& camera);

// World to eye coordinates (right-handed, looking down -z), as OpenGL expects.
Eigen::Matrix4f view_matrix(const OrbitCamera& camera);
// Perspective projection for a viewport of width/height `aspect`, its centre moved by the lens
// shift. The near and far planes follow the distance, so zooming far in or out never clips the
// target.
Eigen::Matrix4f projection_matrix(const OrbitCamera& camera, float aspect);

// How far the mouse may take the camera, in metres. The defaults limit nothing but the
// OrbitCamera's own range.
struct CameraLimits {
  float min_distance = OrbitCamera::min_distance;  // from the target
  float max_distance = OrbitCamera::max_distance;
  float lowest_eye = -std::numeric_limits<float>::infinity();  // the eye's least height (y)
};

// Limits that keep a shape of bounding radius `radius` (m) in a sensible view over a ground at
// `ground_height` (m): the distance within [0.6, 20] × radius (0.6: outside a cube looked at
// square on, whose faces lie 0.58 radius from its centre; 20: the shape still some pixels
// wide), and the eye at least 0.05 × radius above the ground, so the view never looks up
// through it.
CameraLimits camera_limits_for(float radius, float ground_height);

// Mouse gestures, in window pixels. `viewport_height` makes them independent of window size.
// A gesture stops at `limits`; a camera already past one (a view the command line or the scene
// asked for) may come back but goes no further.
// Orbit: a drag across the full height turns the camera by π.
void orbit_camera(OrbitCamera& camera, float dx_pixels, float dy_pixels, float viewport_height,
                  const CameraLimits& limits = CameraLimits());
// Pan: the point under the cursor at the target's depth stays under the cursor.
void pan_camera(OrbitCamera& camera, float dx_pixels, float dy_pixels, float viewport_height,
                const CameraLimits& limits = CameraLimits());
// Zoom: each wheel step (positive = towards the target) divides the distance by 1.15.
void zoom_camera(OrbitCamera& camera, float wheel_steps,
                 const CameraLimits& limits = CameraLimits());

// A part of the viewport, as fractions of its width and height from its top-left corner.
struct ViewportRegion {
  float left = 0.0f, top = 0.0f, right = 1.0f, bottom = 1.0f;
};

// Aim at the centre of the box [lower, upper], show it at the centre of `region` (through the
// lens shift) and move back until its bounding sphere fits the region, keeping the direction of
// view. `aspect` is the whole viewport's width/height.
void frame_box(OrbitCamera& camera, const Eigen::Vector3f& lower, const Eigen::Vector3f& upper,
               float aspect, const ViewportRegion& region = ViewportRegion());

}  // namespace wobble

#endif

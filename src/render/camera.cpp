#include "camera.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace wobble {

namespace {

constexpr float pi = 3.14159265358979f;

float clamp_distance(float distance) {
  return std::clamp(distance, OrbitCamera::min_distance, OrbitCamera::max_distance);
}

// After a gesture, the least height the eye may have: the limit, or where the eye already was
// if that was lower, so that a view begun under the limit never jumps.
float eye_floor(const OrbitCamera& before, const CameraLimits& limits) {
  return std::min(limits.lowest_eye, camera_eye(before).y());
}

// Tilt the view up just enough that the eye is at `floor` or above, if a pitch can.
void raise_pitch(OrbitCamera& camera, float floor) {
  if (camera_eye(camera).y() >= floor) return;
  const float sine = std::min((floor - camera.target.y()) / camera.distance, 1.0f);
  camera.pitch = std::clamp(std::max(camera.pitch, std::asin(sine)), -OrbitCamera::max_pitch,
                            OrbitCamera::max_pitch);
}

}  // namespace

Eigen::Vector3f camera_eye(const OrbitCamera& camera) {
  return camera.target - camera.distance * camera_forward(camera);
}

Eigen::Vector3f camera_forward(const OrbitCamera& camera) {
  const float c = std::cos(camera.pitch);
  return -Eigen::Vector3f(c * std::sin(camera.yaw), std::sin(camera.pitch),
                          c * std::cos(camera.yaw));
}

Eigen::Matrix4f view_matrix(const OrbitCamera& camera) {
  const Eigen::Vector3f forward = camera_forward(camera);
  // The pitch never reaches ±π/2, so forward is never parallel to y.
  const Eigen::Vector3f right = forward.cross(Eigen::Vector3f::UnitY()).normalized();
  const Eigen::Vector3f up = right.cross(forward);
  const Eigen::Vector3f eye = camera_eye(camera);
  Eigen::Matrix4f view = Eigen::Matrix4f::Identity();
  view.block<1, 3>(0, 0) = right.transpose();
  view.block<1, 3>(1, 0) = up.transpose();
  view.block<1, 3>(2, 0) = -forward.transpose();
  view(0, 3) = -right.dot(eye);
  view(1, 3) = -up.dot(eye);
  view(2, 3) = forward.dot(eye);
  return view;
}

Eigen::Matrix4f projection_matrix(const OrbitCamera& camera, float aspect) {
  // Depth precision is spent where the scene is: from 1/100 to 100 times the target distance.
  const float near = 0.01f * camera.distance;
  const float far = 100.0f * camera.distance;
  const float f = 1.0f / std::tan(0.5f * camera.vertical_fov);
  Eigen::Matrix4f projection = Eigen::Matrix4f::Zero();
  projection(0, 0) = f / aspect;
  projection(1, 1) = f;
  projection(2, 2) = (far + near) / (near - far);
  projection(2, 3) = 2.0f * far * near / (near - far);
  projection(3, 2) = -1.0f;
  // x_ndc = f/aspect · x/(-z) − projection(0, 2): the target, on the axis, lands at the shift.
  projection(0, 2) = -camera.lens_shift.x();
  projection(1, 2) = -camera.lens_shift.y();
  return projection;
}

CameraLimits camera_limits_for(float radius, float ground_height) {
  CameraLimits limits;
  radius = std::max(radius, 1e-3f);
  limits.min_distance = std::max(0.6f * radius, OrbitCamera::min_distance);
  limits.max_distance = std::min(20.0f * radius, OrbitCamera::max_distance);
  limits.lowest_eye = ground_height + 0.05f * radius;
  return limits;
}

void orbit_camera(OrbitCamera& camera, float dx_pixels, float dy_pixels, float viewport_height,
                  const CameraLimits& limits) {
  const OrbitCamera before = camera;
  const float radians_per_pixel = pi / std::max(viewport_height, 1.0f);
  camera.yaw -= dx_pixels * radians_per_pixel;
  camera.pitch += dy_pixels * radians_per_pixel;
  camera.pitch = std::clamp(camera.pitch, -OrbitCamera::max_pitch, OrbitCamera::max_pitch);
  camera.yaw = std::remainder(camera.yaw, 2.0f * pi);
  raise_pitch(camera, eye_floor(before, limits));
}

void pan_camera(OrbitCamera& camera, float dx_pixels, float dy_pixels, float viewport_height,
                const CameraLimits& limits) {
  const OrbitCamera before = camera;
  const float metres_per_pixel = 2.0f * camera.distance * std::tan(0.5f * camera.vertical_fov) /
                                 std::max(viewport_height, 1.0f);
  const Eigen::Vector3f forward = camera_forward(camera);
  const Eigen::Vector3f right = forward.cross(Eigen::Vector3f::UnitY()).normalized();
  const Eigen::Vector3f up = right.cross(forward);
  // Dragging right moves the scene right, so the target moves left.
  camera.target += metres_per_pixel * (-dx_pixels * right + dy_pixels * up);
  // Panning down would take the eye under the ground: the camera stops there, lifted straight
  // up rather than turned, so the view keeps its direction.
  const float floor = eye_floor(before, limits);
  const float eye_height = camera_eye(camera).y();
  if (eye_height < floor) camera.target.y() += floor - eye_height;
}

void zoom_camera(OrbitCamera& camera, float wheel_steps, const CameraLimits& limits) {
  const OrbitCamera before = camera;
  const float nearest = std::min(limits.min_distance, camera.distance);
  const float farthest = std::max(limits.max_distance, camera.distance);
  camera.distance = clamp_distance(
      std::clamp(camera.distance * std::pow(1.15f, -wheel_steps), nearest, farthest));
  // Backing away while looking up lowers the eye: it tilts to stay above the ground.
  raise_pitch(camera, eye_floor(before, limits));
}

void frame_box(OrbitCamera& camera, const Eigen::Vector3f& lower, const Eigen::Vector3f& upper,
               float aspect, const ViewportRegion& region) {
  camera.target = 0.5f * (lower + upper);
  const float radius = std::max(0.5f * (upper - lower).norm(), 1e-3f);
  // The region in normalized device coordinates (y up): its centre and half-size.
  const float half_width = region.right - region.left;
  const float half_height = region.bottom - region.top;
  camera.lens_shift =
      Eigen::Vector2f(region.left + region.right - 1.0f, 1.0f - (region.top + region.bottom));
  // The sphere fits where its angular radius reaches the nearer pair of the region's edges
  // (exact on the axis; off it, the perspective widens the sphere's image by a few per cent,
  // which the sphere's slack around a box makes up for).
  const float half_vertical = 0.5f * camera.vertical_fov;
  const float vertical =
      half_height == 1.0f ? half_vertical : std::atan(std::tan(half_vertical) * half_height);
  const float horizontal = std::atan(std::tan(half_vertical) * aspect * half_width);
  camera.distance = clamp_distance(radius / std::sin(std::min(vertical, horizontal)));
}

}  // namespace wobble

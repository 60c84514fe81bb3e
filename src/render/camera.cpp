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
  return projection;
}

void orbit_camera(OrbitCamera& camera, float dx_pixels, float dy_pixels, float viewport_height) {
  const float radians_per_pixel = pi / std::max(viewport_height, 1.0f);
  camera.yaw -= dx_pixels * radians_per_pixel;
  camera.pitch += dy_pixels * radians_per_pixel;
  camera.pitch = std::clamp(camera.pitch, -OrbitCamera::max_pitch, OrbitCamera::max_pitch);
  camera.yaw = std::remainder(camera.yaw, 2.0f * pi);
}

void pan_camera(OrbitCamera& camera, float dx_pixels, float dy_pixels, float viewport_height) {
  const float metres_per_pixel = 2.0f * camera.distance * std::tan(0.5f * camera.vertical_fov) /
                                 std::max(viewport_height, 1.0f);
  const Eigen::Vector3f forward = camera_forward(camera);
  const Eigen::Vector3f right = forward.cross(Eigen::Vector3f::UnitY()).normalized();
  const Eigen::Vector3f up = right.cross(forward);
  // Dragging right moves the scene right, so the target moves left.
  camera.target += metres_per_pixel * (-dx_pixels * right + dy_pixels * up);
}

void zoom_camera(OrbitCamera& camera, float wheel_steps) {
  camera.distance = clamp_distance(camera.distance * std::pow(1.15f, -wheel_steps));
}

void frame_box(OrbitCamera& camera, const Eigen::Vector3f& lower, const Eigen::Vector3f& upper,
               float aspect) {
  camera.target = 0.5f * (lower + upper);
  const float radius = std::max(0.5f * (upper - lower).norm(), 1e-3f);
  const float half_vertical = 0.5f * camera.vertical_fov;
  const float half_horizontal = std::atan(std::tan(half_vertical) * aspect);
  camera.distance = clamp_distance(radius / std::sin(std::min(half_vertical, half_horizontal)));
}

}  // namespace wobble

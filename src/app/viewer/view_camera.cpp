// The viewer's camera: the view a scene opens with, framing (on load, F and O), and the limits
// that keep the mouse from taking the camera under the ground, into the shape or far away.
#include "app/viewer/view_camera.h"

#include <algorithm>
#include <cmath>

#include "app/interaction/view_framing.h"

namespace wobble {

namespace {

constexpr float degrees = 3.14159265358979f / 180.0f;
// The view a scene opens with: from the front right, a little above.
constexpr float default_yaw = 30.0f * degrees;
constexpr float default_pitch = 20.0f * degrees;

void bounds(const float* positions, int count, Eigen::Vector3f& lower, Eigen::Vector3f& upper) {
  lower = upper = Eigen::Vector3f::Zero();
  for (int i = 0; i < count; ++i) {
    const Eigen::Map<const Eigen::Vector3f> p(positions + 3 * i);
    lower = i == 0 ? Eigen::Vector3f(p) : Eigen::Vector3f(lower.cwiseMin(p));
    upper = i == 0 ? Eigen::Vector3f(p) : Eigen::Vector3f(upper.cwiseMax(p));
  }
}

}  // namespace

ViewCamera::ViewCamera(std::optional<float> yaw, std::optional<float> pitch, float zoom)
    : start_yaw_(yaw), start_zoom_(zoom > 0.0f && std::isfinite(zoom) ? zoom : 1.0f) {
  if (pitch) start_pitch_ = std::clamp(*pitch, -OrbitCamera::max_pitch, OrbitCamera::max_pitch);
  camera_.yaw = start_yaw_.value_or(default_yaw);
  camera_.pitch = start_pitch_.value_or(default_pitch);
}

void ViewCamera::open(const SceneLook& look, const Eigen::MatrixXd& rest, float ground_height) {
  frame_pending_ = true;
  zoom_framing_ = true;
  scene_camera_.reset();
  scene_yaw_ = default_yaw;
  scene_pitch_ = default_pitch;
  if (look.camera_position && look.camera_target) {
    // The scene's own view replaces the framing; --camera-yaw/--camera-pitch still turn it.
    const Eigen::Vector3f eye = look.camera_position->cast<float>();
    const Eigen::Vector3f target = look.camera_target->cast<float>();
    const Eigen::Vector3f back = eye - target;
    camera_.target = target;
    camera_.distance = std::max(back.norm(), OrbitCamera::min_distance);
    camera_.yaw = std::atan2(back.x(), back.z());
    camera_.pitch = std::clamp(std::asin(std::clamp(back.y() / camera_.distance, -1.0f, 1.0f)),
                               -OrbitCamera::max_pitch, OrbitCamera::max_pitch);
    camera_.lens_shift.setZero();
    scene_yaw_ = camera_.yaw;
    scene_pitch_ = camera_.pitch;
    if (start_yaw_) camera_.yaw = *start_yaw_;
    if (start_pitch_) camera_.pitch = *start_pitch_;
    scene_camera_ = camera_;
    fit_scene_camera_ = true;  // into what the panel and the plots leave free, at frame()
  }
  opening_yaw_ = camera_.yaw;
  opening_pitch_ = camera_.pitch;
  // The limits scale with the shape at rest, which is what the opening view frames; a shape
  // stretched far later still gets the same room to zoom.
  const float radius =
      rest.rows() > 0
          ? 0.5f *
                static_cast<float>((rest.colwise().maxCoeff() - rest.colwise().minCoeff()).norm())
          : 1.0f;
  limits_ = camera_limits_for(radius, ground_height);
}

void ViewCamera::restore_opening_view() {
  zoom_framing_ = true;
  if (scene_camera_) {
    camera_ = *scene_camera_;
    fit_scene_camera_ = true;
    frame_pending_ = true;
    return;
  }
  camera_.yaw = opening_yaw_;
  camera_.pitch = opening_pitch_;
  frame_pending_ = true;
}

void ViewCamera::frame(const std::vector<float>& positions, float ground_height,
                       const ViewportRegion& region, float aspect) {
  if (!frame_pending_) return;
  frame_pending_ = false;
  if (fit_scene_camera_) {
    // The scene's own view, made for the whole window, into the part of it left free: the same
    // target at the free part's centre, from as much farther away as the part is narrower, so
    // that what the scene framed across the window fits across the part.
    fit_scene_camera_ = false;
    camera_ = *scene_camera_;
    const float width = region.right - region.left, height = region.bottom - region.top;
    const float part = std::min(width, height);
    if (part > 0.0f && part < 1.0f) {
      camera_.distance = std::min(camera_.distance / part, OrbitCamera::max_distance);
      camera_.lens_shift =
          Eigen::Vector2f(region.left + region.right - 1.0f, 1.0f - (region.top + region.bottom));
    }
    framed();
    return;
  }
  Eigen::Vector3f lower, upper;
  bounds(positions.data(), static_cast<int>(positions.size() / 3), lower, upper);
  // Always with room to move, on load and on F alike: F right after R sees the flat cloth it
  // is about to drop, and a tight frame around it loses the cloth within a second. Where a
  // shape will go is known only roughly, but the ground bounds it below, and the box still
  // holds the shape wherever it is now (thrown high, the frame only grows).
  add_room_to_move(lower, upper, ground_height);
  frame_box(camera_, lower, upper, aspect, region);
  framed();
}

void ViewCamera::framed() {
  framed_distance_ = camera_.distance;
  framed_target_ = camera_.target;
  // The opening view (and O's), framed again as the panel settles, keeps --camera-zoom; F does
  // not.
  if (zoom_framing_) {
    camera_.distance = std::clamp(camera_.distance / start_zoom_, OrbitCamera::min_distance,
                                  OrbitCamera::max_distance);
  }
}

ViewCamera::Angles ViewCamera::angles() const {
  constexpr double to_degrees = 180.0 / 3.14159265358979323846;
  Angles angles;
  angles.yaw_degrees = std::remainder(static_cast<double>(camera_.yaw) * to_degrees, 360.0);
  if (angles.yaw_degrees <= -180.0) angles.yaw_degrees += 360.0;
  angles.pitch_degrees = camera_.pitch * to_degrees;
  angles.zoom = camera_.distance > 0.0f ? framed_distance_ / camera_.distance : 1.0;
  angles.scene_yaw_degrees = scene_yaw_ * to_degrees;
  angles.scene_pitch_degrees = scene_pitch_ * to_degrees;
  angles.panned = (camera_.target - framed_target_).norm() > 1e-4f * framed_distance_;
  return angles;
}

void ViewCamera::orbit(float dx, float dy, float view_height) {
  orbit_camera(camera_, dx, dy, view_height, limits_);
}

void ViewCamera::pan(float dx, float dy, float view_height) {
  pan_camera(camera_, dx, dy, view_height, limits_);
}

void ViewCamera::zoom(float wheel) {
  zoom_camera(camera_, wheel, limits_);
}

}  // namespace wobble

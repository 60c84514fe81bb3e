// The viewer's camera: the view a scene opens with, framing (on load, F and O), and the limits
// that keep the mouse from taking the camera under the ground, into the shape or far away.
#include <algorithm>
#include <cmath>

#include "app/interaction/view_framing.h"
#include "app/viewer/viewer.h"

namespace wobble {

namespace {

void bounds(const float* positions, int count, Eigen::Vector3f& lower, Eigen::Vector3f& upper) {
  lower = upper = Eigen::Vector3f::Zero();
  for (int i = 0; i < count; ++i) {
    const Eigen::Map<const Eigen::Vector3f> p(positions + 3 * i);
    lower = i == 0 ? Eigen::Vector3f(p) : Eigen::Vector3f(lower.cwiseMin(p));
    upper = i == 0 ? Eigen::Vector3f(p) : Eigen::Vector3f(upper.cwiseMax(p));
  }
}

}  // namespace

void Viewer::open_view() {
  frame_on_next_render_ = true;
  scene_camera_.reset();
  const SceneLook& look = scene_.look;
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
    if (settings_yaw_) camera_.yaw = *settings_yaw_;
    if (settings_pitch_) camera_.pitch = *settings_pitch_;
    scene_camera_ = camera_;
    frame_on_next_render_ = false;
  }
  opening_yaw_ = camera_.yaw;
  opening_pitch_ = camera_.pitch;
  // The limits scale with the shape at rest, which is what the opening view frames; a shape
  // stretched far later still gets the same room to zoom.
  const Eigen::MatrixXd& V = scene_.network.V;
  const float radius =
      V.rows() > 0
          ? 0.5f * static_cast<float>((V.colwise().maxCoeff() - V.colwise().minCoeff()).norm())
          : 1.0f;
  camera_limits_ = camera_limits_for(radius, ground_.height);
}

void Viewer::restore_opening_view() {
  if (scene_camera_) {
    camera_ = *scene_camera_;
    frame_on_next_render_ = false;
    return;
  }
  camera_.yaw = opening_yaw_;
  camera_.pitch = opening_pitch_;
  frame_on_next_render_ = true;
}

void Viewer::frame_camera(float aspect) {
  Eigen::Vector3f lower, upper;
  bounds(positions_.data(), static_cast<int>(positions_.size() / 3), lower, upper);
  // Always with room to move, on load and on F alike: F right after R sees the flat cloth it
  // is about to drop, and a tight frame around it loses the cloth within a second. Where a
  // shape will go is known only roughly, but the ground bounds it below, and the box still
  // holds the shape wherever it is now (thrown high, the frame only grows).
  add_room_to_move(lower, upper, ground_.height);
  // Split, the panel covers only the left side, but both sides share one camera: each is framed
  // whole.
  const ViewportRegion region = panel_place_.shown && !twin_
                                    ? region_beside_panel(window_size_.x(), panel_place_.x,
                                                          panel_place_.x + panel_place_.width)
                                    : ViewportRegion();
  frame_box(camera_, lower, upper, aspect, region);
  frame_on_next_render_ = false;
}

}  // namespace wobble

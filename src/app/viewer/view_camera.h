#ifndef WOBBLE_APP_VIEWER_VIEW_CAMERA_H
#define WOBBLE_APP_VIEWER_VIEW_CAMERA_H

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "render/camera.h"
#include "sim/scene.h"

namespace wobble {

// The viewer's camera, a component of the viewer: the view a scene opens with (its own camera,
// or a framing from the command line's angles or the default ones), framing on load, F and O,
// and the limits that keep the mouse from taking the camera under the ground, into the shape
// or far away. It owns its state; the viewer asks it to open a scene, to frame, and to move.
class ViewCamera {
 public:
  // The angles every scene opens from (radians), from --camera-yaw and --camera-pitch; unset,
  // from the front right, a little above; and `zoom` times nearer than its framing
  // (--camera-zoom).
  ViewCamera(std::optional<float> yaw, std::optional<float> pitch, float zoom = 1.0f);

  // A scene opens: its own view if it has one (the angles above still turn it), fitted at the
  // next frame() into the region left free (from farther away, as the region is narrower than
  // the view), else a framing at the next frame(). `rest` is #V by 3 (m); `ground_height` (m)
  // bounds the limits.
  void open(const SceneLook& look, const Eigen::MatrixXd& rest, float ground_height);
  // O: the view the scene opened with.
  void restore_opening_view();
  // F, a new split or its end: frame at the next frame().
  void frame_next() {
    frame_pending_ = true;
    fit_scene_camera_ = false;
  }
  // F: a framing of the shape as it is now, without --camera-zoom.
  void frame_shape() {
    frame_next();
    zoom_framing_ = false;
  }
  // A framing (or the scene's own view) waits for the next frame().
  bool framing_pending() const { return frame_pending_; }
  // Centre the view on the shape (a split view's halves), keeping the direction.
  void centre() { camera_.lens_shift.setZero(); }
  // If a framing is pending: the shape at `positions` (#V by 3 floats, m) with room to move
  // down to `ground_height`, in `region` of a view of `aspect` (width / height).
  void frame(const std::vector<float>& positions, float ground_height, const ViewportRegion& region,
             float aspect);

  // The mouse: deltas in window units, over a view `view_height` tall.
  void orbit(float dx, float dy, float view_height);
  void pan(float dx, float dy, float view_height);
  void zoom(float wheel);

  const OrbitCamera& camera() const { return camera_; }

  // The view as the command line's angles and zoom give it back (the page's Copy link): the
  // angles (degrees, yaw in (-180, 180]), how many times nearer than the last framing the camera
  // is, and the scene's own angles, as it opens without --camera-yaw and --camera-pitch.
  // `panned`: the target moved since the framing, which the angles and zoom do not carry.
  struct Angles {
    double yaw_degrees = 0.0, pitch_degrees = 0.0, zoom = 1.0;
    double scene_yaw_degrees = 0.0, scene_pitch_degrees = 0.0;
    bool panned = false;
  };
  Angles angles() const;
  const CameraLimits& limits() const { return limits_; }

 private:
  void framed();  // after a framing: remembered, and the opening view's zoom
  OrbitCamera camera_;
  std::optional<float> start_yaw_, start_pitch_;  // radians, from the command line
  float start_zoom_ = 1.0f;                       // times nearer than the framing
  bool zoom_framing_ = true;      // the next framings are the opening view's: start_zoom_ nearer
  float framed_distance_ = 0.0f;  // the last framing's distance and target, before the zoom
  Eigen::Vector3f framed_target_ = Eigen::Vector3f::Zero();
  float scene_yaw_ = 0.0f, scene_pitch_ = 0.0f;  // the scene's own angles (radians)
  bool frame_pending_ = true;
  bool fit_scene_camera_ = false;  // the pending framing is the scene's own view, fitted
  // The view the scene opened with: its own camera, or the angles it was framed from.
  std::optional<OrbitCamera> scene_camera_;
  float opening_yaw_ = 0.0f, opening_pitch_ = 0.0f;
  CameraLimits limits_;
};

}  // namespace wobble

#endif

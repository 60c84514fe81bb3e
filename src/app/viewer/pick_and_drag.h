#ifndef WOBBLE_APP_VIEWER_PICK_AND_DRAG_H
#define WOBBLE_APP_VIEWER_PICK_AND_DRAG_H

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "app/interaction/collider_drag.h"
#include "app/interaction/picking.h"
#include "app/interaction/vertex_drag.h"
#include "app/viewer/view_camera.h"
#include "platform/input_event.h"
#include "sim/simulation.h"

namespace wobble {

// The picture the mouse points into, as the viewer last drew it: what picking reads.
struct PointerView {
  Eigen::Matrix4f view = Eigen::Matrix4f::Identity();        // the last render's camera
  Eigen::Matrix4f projection = Eigen::Matrix4f::Identity();  //
  const std::vector<float>* positions = nullptr;             // #V by 3 (m), as drawn
  const std::vector<unsigned char>* pinned = nullptr;        // #V flags, non-zero: pinned
  // One view's size (window units): the window's, or one half's of a split view, whose two
  // halves stand side by side from `left` under the same camera.
  Eigen::Vector2f size = Eigen::Vector2f(1.0f, 1.0f);
  bool split = false;
  float left = 0.0f;
};

// What a gesture acts on, handed in by the viewer with each frame's events.
struct PointerContext {
  PointerView picture;
  ViewCamera& camera;            // orbit, pan and zoom
  const Simulation& simulation;  // read only: the colliders an Alt press may grab
  bool colliders_shown = true;   // hidden colliders cannot be grabbed
  // A student's step on the right pins its vertices where they rest: the mouse only moves the
  // camera.
  bool camera_only = false;
  // Hands an edit of the simulation to the viewer, which makes it at once between batches of
  // steps, or, in order, once the running batch finished.
  std::function<void(std::function<void(Simulation&)>)> change = nullptr;
};

// Picking and drags, a component of the viewer: what the mouse does in the 3-D view. A press
// grabs a pin or a free vertex (VertexDrag), Alt grabs a collider (ColliderDrag), Ctrl toggles
// a pin, and on empty space the mouse turns or slides the camera; the wheel zooms. It owns the
// gesture in progress and the cursor; the simulation it changes only through the context's
// `change`, and what it holds it decides at once, on the picture drawn. On the UI's side.
class PickAndDrag {
 public:
  // How close, in window units, the cursor must come to a vertex to pick it.
  static constexpr float pick_radius = 8.0f;

  // The frame's events begin. `ui_wants_mouse` is ImGui's io.WantCaptureMouse: the panel has
  // the mouse, so that nothing under it is grabbed, zoomed or highlighted.
  void begin_events(bool ui_wants_mouse) { over_ui_ = ui_wants_mouse; }
  // A button press or release, a cursor move or the wheel (window units); keys are not the
  // mouse's. Returns whether it took the event: started or ended a gesture, moved what it
  // holds or the camera.
  bool mouse_event(const InputEvent& event, PointerContext& context);
  // The marks the renderer draws for each vertex of `picture` into `marks` (#V): 1 on a pin,
  // 2 on the pin under the cursor and on the vertex held.
  void mark(const PointerView& picture, std::vector<unsigned char>& marks) const;

  // A vertex or collider is held (its grab may still wait for the running batch).
  bool holds() const { return holds_; }
  // Holding something or turning the camera: the next frames change without input.
  bool busy() const { return holds_ || mode_ != Mode::idle; }
  // The vertex the mouse drags in the simulation now, or -1.
  int held_vertex() const { return drag_.active() ? drag_.vertex() : -1; }
  // A free vertex held: pinned only for the drag, so not one of the pins.
  bool holds_free_vertex() const { return drag_.holds_free_vertex(); }

  // The simulation was reset (the simulation's side): what was held is forgotten, the
  // colliders are back where they started; the button, still down, grabs nothing more.
  void cancel_drags() {
    drag_.cancel();
    collider_drag_.cancel();
  }
  // The colliders were hidden: one held is let go where it is.
  void drop_collider() { collider_drag_.cancel(); }
  // A new scene: no gesture, nothing held.
  void forget() {
    cancel_drags();
    holds_ = false;
    mode_ = Mode::idle;
  }

 private:
  bool press(const InputEvent& event, const Eigen::Vector2f& at, PointerContext& context);
  // The point under `raw` (window units) in its view: split, a cursor in the right half picks
  // as at the same place in the left (pins and drags are shared).
  static Eigen::Vector2f in_view(const PointerView& picture, const Eigen::Vector2f& raw);
  static int pick(const PointerView& picture, const Eigen::Vector2f& cursor, bool pinned_only);
  static Ray ray_at(const PointerView& picture, const Eigen::Vector2f& cursor);

  enum class Mode { idle, orbit, pan } mode_ = Mode::idle;
  VertexDrag drag_;
  ColliderDrag collider_drag_;
  bool holds_ = false;
  bool over_ui_ = false;
  Eigen::Vector2f cursor_ = Eigen::Vector2f(-1e9f, -1e9f);      // in the view under it
  Eigen::Vector2f raw_cursor_ = Eigen::Vector2f(-1e9f, -1e9f);  // in the window
};

}  // namespace wobble

#endif

// What the mouse does in the viewer's 3-D view: grabbing and dragging pins, vertices and
// colliders, toggling pins, turning, sliding and zooming the camera.
#include "app/viewer/pick_and_drag.h"

#include <optional>

#include "app/interaction/collider_picking.h"
#include "app/interaction/input_mapping.h"
#include "render/camera.h"
#include "sim/contact/collider_contact_term.h"

namespace wobble {

Eigen::Vector2f PickAndDrag::in_view(const PointerView& picture, const Eigen::Vector2f& raw) {
  Eigen::Vector2f at = raw;
  if (picture.split) {
    at.x() -= picture.left;
    if (at.x() >= picture.size.x()) at.x() -= picture.size.x();
  }
  return at;
}

int PickAndDrag::pick(const PointerView& picture, const Eigen::Vector2f& cursor, bool pinned_only) {
  return pick_vertex(picture.projection * picture.view, picture.positions->data(),
                     static_cast<int>(picture.positions->size() / 3),
                     pinned_only ? picture.pinned->data() : nullptr, cursor, picture.size,
                     pick_radius);
}

Ray PickAndDrag::ray_at(const PointerView& picture, const Eigen::Vector2f& cursor) {
  return cursor_ray(picture.view, picture.projection, cursor, picture.size);
}

bool PickAndDrag::mouse_event(const InputEvent& event, PointerContext& context) {
  const Eigen::Vector2f raw(static_cast<float>(event.x), static_cast<float>(event.y));
  const Eigen::Vector2f at = in_view(context.picture, raw);
  switch (event.type) {
    case InputEvent::Type::button_press:
      return press(event, at, context);
    case InputEvent::Type::button_release: {
      const bool took = busy();
      if (holds_) {
        context.change([this](Simulation& simulation) {
          drag_.release(simulation);
          collider_drag_.release();
        });
      }
      holds_ = false;
      mode_ = Mode::idle;
      return took;
    }
    case InputEvent::Type::cursor_move: {
      const Eigen::Vector2f delta = raw - raw_cursor_;
      raw_cursor_ = raw;
      cursor_ = at;
      if (holds_) {
        context.change([this, ray = ray_at(context.picture, at)](Simulation& simulation) {
          if (drag_.active()) drag_.move(simulation, ray);
          if (collider_drag_.active()) collider_drag_.move(simulation, ray);
        });
      }
      const float view_height = context.picture.size.y();
      if (mode_ == Mode::orbit) context.camera.orbit(delta.x(), delta.y(), view_height);
      if (mode_ == Mode::pan) context.camera.pan(delta.x(), delta.y(), view_height);
      return busy();
    }
    case InputEvent::Type::scroll:
      if (over_ui_) return false;
      context.camera.zoom(static_cast<float>(event.y));
      return true;
    case InputEvent::Type::key_press:
      return false;
  }
  return false;
}

bool PickAndDrag::press(const InputEvent& event, const Eigen::Vector2f& at,
                        PointerContext& context) {
  // One gesture at a time.
  if (busy()) return false;
  const PointerView& picture = context.picture;
  const int pin = pick(picture, at, /*pinned_only=*/true);
  const int vertex = pin >= 0 ? pin : pick(picture, at, /*pinned_only=*/false);
  const Ray ray = ray_at(picture, at);
  const std::optional<ColliderHit> collider =
      event.alt && context.colliders_shown
          ? pick_collider(ray, colliders_in(context.simulation.terms()))
          : std::nullopt;
  MouseGesture gesture = gesture_for_press(event.code, event.control, event.shift, over_ui_,
                                           pin >= 0, vertex >= 0, event.alt, collider.has_value());
  if (context.camera_only && gesture != MouseGesture::orbit && gesture != MouseGesture::pan) {
    gesture = MouseGesture::none;
  }
  // What the gesture does to the simulation waits for a running batch; the camera and what the
  // mouse holds are decided now, on the picture drawn.
  const Eigen::Vector3f forward = camera_forward(context.camera.camera());
  switch (gesture) {
    case MouseGesture::grab_collider:
      holds_ = true;
      context.change([this, hit = *collider, forward](Simulation& simulation) {
        collider_drag_.grab(simulation, hit.index, hit.point, forward);
      });
      return true;
    case MouseGesture::grab_pin:
    case MouseGesture::grab_free_vertex:
      holds_ = true;
      context.change([this, vertex, ray, forward](Simulation& simulation) {
        drag_.grab(simulation, vertex, ray, forward);
      });
      return true;
    case MouseGesture::toggle_pin:
      context.change([vertex](Simulation& simulation) {
        if (simulation.is_pinned(vertex)) {
          simulation.unpin(vertex);
        } else {
          simulation.pin(vertex);
        }
      });
      return true;
    case MouseGesture::orbit:
      mode_ = Mode::orbit;
      return true;
    case MouseGesture::pan:
      mode_ = Mode::pan;
      return true;
    case MouseGesture::none:
      return false;
  }
  return false;
}

void PickAndDrag::mark(const PointerView& picture, std::vector<unsigned char>& marks) const {
  // The pin under the cursor and the vertex being held are highlighted.
  const int hovered = !busy() && !over_ui_ ? pick(picture, cursor_, /*pinned_only=*/true) : -1;
  marks.assign(picture.pinned->begin(), picture.pinned->end());
  if (hovered >= 0) marks[hovered] = 2;
  if (drag_.active()) marks[drag_.vertex()] = 2;
}

}  // namespace wobble

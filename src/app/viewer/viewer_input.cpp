// The viewer's mouse and keys: what each event does to the camera, the pins and the playback.
#include <algorithm>

#include "app/cli/scene_catalog.h"
#include "app/interaction/collider_picking.h"
#include "app/interaction/environment_controls.h"
#include "app/viewer/scene_save.h"
#include "app/viewer/viewer.h"
#include "app/viewer/window_saves.h"
#include "io/write_obj.h"

namespace wobble {

namespace {

// How close, in window units, the cursor must come to a vertex to pick it.
constexpr float pick_radius = 8.0f;

}  // namespace

int Viewer::pick(const Eigen::Vector2f& cursor, bool pinned_only) const {
  return pick_vertex(
      projection_ * view_, positions_.data(), static_cast<int>(positions_.size() / 3),
      pinned_only ? pinned_flags_.data() : nullptr, cursor, window_size_, pick_radius);
}

Ray Viewer::ray_at(const Eigen::Vector2f& cursor) const {
  return cursor_ray(view_, projection_, cursor, window_size_);
}

void Viewer::handle_events(const std::vector<InputEvent>& events, bool ui_wants_mouse,
                           bool ui_wants_keyboard, const Eigen::Vector2f& window_size) {
  // Split, each half is a view of its own under the same camera: a cursor in the right half
  // picks and drags as at the same place in the left (pins and drags are shared).
  const SplitArea area = split_area(window_size.x());
  window_size_ = right_.simulation() ? Eigen::Vector2f(area.half, window_size.y()) : window_size;
  cursor_over_ui_ = ui_wants_mouse;
  for (const InputEvent& event : events) {
    const Eigen::Vector2f raw(static_cast<float>(event.x), static_cast<float>(event.y));
    Eigen::Vector2f at = raw;
    if (right_.simulation()) {
      at.x() -= area.left;
      if (at.x() >= area.half) at.x() -= area.half;
    }
    switch (event.type) {
      case InputEvent::Type::key_press:
        if (!ui_wants_keyboard) apply(command_for_key(event.code, event.control));
        break;
      case InputEvent::Type::button_press: {
        // One gesture at a time.
        if (mouse_holds_ || mode_ != Mode::idle) break;
        const int pin = pick(at, /*pinned_only=*/true);
        const int vertex = pin >= 0 ? pin : pick(at, /*pinned_only=*/false);
        // Hidden colliders cannot be grabbed.
        const std::optional<ColliderHit> collider =
            event.alt && panel_.colliders ? pick_collider(ray_at(at), simulation_->colliders())
                                          : std::nullopt;
        MouseGesture gesture =
            gesture_for_press(event.code, event.control, event.shift, ui_wants_mouse, pin >= 0,
                              vertex >= 0, event.alt, collider.has_value());
        // The student's step pins its vertices where they rest: with a student on the right,
        // the mouse only moves the camera.
        if (right_.student() && gesture != MouseGesture::orbit && gesture != MouseGesture::pan) {
          gesture = MouseGesture::none;
        }
        // What the gesture does to the simulation waits for a running batch; the camera and
        // what the mouse holds are decided now, on the state drawn.
        const Ray ray = ray_at(at);
        const Eigen::Vector3f forward = camera_forward(view_camera_.camera());
        switch (gesture) {
          case MouseGesture::grab_collider:
            mouse_holds_ = true;
            change([this, hit = *collider, forward] {
              collider_drag_.grab(*simulation_, hit.index, hit.point, forward);
            });
            break;
          case MouseGesture::grab_pin:
          case MouseGesture::grab_free_vertex:
            mouse_holds_ = true;
            change(
                [this, vertex, ray, forward] { drag_.grab(*simulation_, vertex, ray, forward); });
            break;
          case MouseGesture::toggle_pin:
            change([this, vertex] {
              if (simulation_->is_pinned(vertex)) {
                simulation_->unpin(vertex);
              } else {
                simulation_->pin(vertex);
              }
            });
            break;
          case MouseGesture::orbit:
            mode_ = Mode::orbit;
            break;
          case MouseGesture::pan:
            mode_ = Mode::pan;
            break;
          case MouseGesture::none:
            break;
        }
        break;
      }
      case InputEvent::Type::button_release:
        if (mouse_holds_) {
          change([this] {
            drag_.release(*simulation_);
            collider_drag_.release();
          });
        }
        mouse_holds_ = false;
        mode_ = Mode::idle;
        break;
      case InputEvent::Type::cursor_move: {
        const Eigen::Vector2f delta = raw - raw_cursor_;
        raw_cursor_ = raw;
        if (mouse_holds_) {
          change([this, ray = ray_at(at)] {
            if (drag_.active()) drag_.move(*simulation_, ray);
            if (collider_drag_.active()) collider_drag_.move(*simulation_, ray);
          });
        }
        if (mode_ == Mode::orbit) {
          view_camera_.orbit(delta.x(), delta.y(), window_size_.y());
        }
        if (mode_ == Mode::pan) {
          view_camera_.pan(delta.x(), delta.y(), window_size_.y());
        }
        cursor_ = at;
        break;
      }
      case InputEvent::Type::scroll:
        if (!ui_wants_mouse) view_camera_.zoom(static_cast<float>(event.y));
        break;
    }
  }
}

void Viewer::save_scene() {
  const std::string path = unused_file_name(".", "wobble-" + scene_.name + "-scene", ".json");
  try {
    const Eigen::Vector3d eye = camera_eye(view_camera_.camera()).cast<double>();
    save_current_scene(
        path, scene_, *simulation_,
        std::make_pair(eye, Eigen::Vector3d(view_camera_.camera().target.cast<double>())));
    // The picker offers it from now on, under its own name.
    if (std::find(scene_sources_.begin(), scene_sources_.end(), path) == scene_sources_.end()) {
      scene_sources_.push_back(path);
      scene_labels_.push_back(scene_label(path));
    }
    saved("saved the scene as " + path + " (wobble " + path +
          " opens it; the scene picker lists it as " + scene_label(path) + ")");
  } catch (const std::exception& error) {
    saved(std::string("saving the scene failed: ") + error.what());
  }
}

void Viewer::apply(ViewerCommand command) {
  switch (command) {
    case ViewerCommand::toggle_pause:
      panel_.paused = !panel_.paused;
      break;
    case ViewerCommand::step_once:
      panel_.paused = true;
      step_requested_ = true;
      break;
    case ViewerCommand::reset:
      change([this] {
        if (drag_.active()) drag_.cancel();
        collider_drag_.cancel();  // reset puts the colliders back
        simulation_->reset();
        right_.reset(scene_, *simulation_);
        instruments_.clear();
        drag_script_.restart();
        step_warning_.clear();
      });
      break;
    case ViewerCommand::toggle_split:
      panel_.split = !panel_.split;
      change([this] { apply_split_settings(); });
      break;
    case ViewerCommand::toggle_plots: {
      // Both plots together: a class wants the two side by side.
      const bool show = !(panel_.show_convergence && panel_.show_energy);
      panel_.show_convergence = panel_.show_energy = show;
      change([this] { update_recording(); });
      break;
    }
    case ViewerCommand::toggle_wireframe:
      panel_.wireframe = !panel_.wireframe;
      break;
    case ViewerCommand::toggle_wind:
      change([this] {
        simulation_->set_wind(toggled_wind(simulation_->params().wind));
        show_environment_in_panel();
      });
      break;
    case ViewerCommand::toggle_colliders:
      panel_.colliders = !panel_.colliders;
      if (!panel_.colliders) collider_drag_.cancel();
      break;
    case ViewerCommand::toggle_points:
      panel_.points = !panel_.points;
      break;
    case ViewerCommand::toggle_springs:
      panel_.springs = !panel_.springs;
      break;
    case ViewerCommand::cycle_color_by:
      panel_.color_by = static_cast<int>(next_color_quantity(color_by()));
      break;
    case ViewerCommand::toggle_help:
      panel_.show_help = !panel_.show_help;
      break;
    case ViewerCommand::frame_mesh:
      view_camera_.frame_next();
      break;
    case ViewerCommand::default_view:
      view_camera_.restore_opening_view();
      break;
    case ViewerCommand::quit:
      quit_ = true;
      break;
    case ViewerCommand::toggle_panel:
      panel_.show_panel = !panel_.show_panel;
      break;
    case ViewerCommand::screenshot:
      screenshot_requested_ = true;
      break;
    case ViewerCommand::export_obj:
      // The state the user sees, once a running batch finished.
      change([this] {
        const std::string path = unused_file_name(".", "wobble-" + scene_.name, ".obj");
        try {
          write_obj(path, simulation_->positions(), scene_.network.F, scene_.network.E);
          saved("exported " + path);
        } catch (const std::exception& error) {
          saved(std::string("export failed: ") + error.what());
        }
      });
      break;
    case ViewerCommand::save_scene:
      change([this] { save_scene(); });  // the settings of the state drawn
      break;
    case ViewerCommand::toggle_record:
      panel_.recording = !panel_.recording;
      break;
    case ViewerCommand::close_overlays:
      panel_.show_help = false;
      break;
    case ViewerCommand::none:
      break;
  }
}

}  // namespace wobble

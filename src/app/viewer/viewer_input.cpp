// The viewer's mouse and keys: what each event does to the camera, the pins and the playback.
#include <algorithm>

#include "app/cli/scene_catalog.h"
#include "app/viewer/viewer.h"
#include "sim/settings/setting_registry.h"

namespace wobble {

PointerView Viewer::pointer_view(const Eigen::Vector2f& window_size) const {
  // Split, each half is a view of its own under the same camera.
  PointerView picture;
  picture.view = view_;
  picture.projection = projection_;
  picture.positions = &positions_;
  picture.pinned = &pinned_flags_;
  picture.size = window_size;
  if (right_.simulation()) {
    const SplitArea area = split_area(window_size.x());
    picture.size = Eigen::Vector2f(area.half, window_size.y());
    picture.split = true;
    picture.left = area.left;
  }
  return picture;
}

void Viewer::handle_events(const std::vector<InputEvent>& events, bool ui_wants_mouse,
                           bool ui_wants_keyboard, const Eigen::Vector2f& window_size) {
  // The simulation a change edits is the one there when the change is made, not as now.
  PointerContext context{pointer_view(window_size), view_camera_, host_.simulation()};
  // The simulation a change edits is the one there when the change is made, not as now.
  context.change = [this](std::function<void(Simulation&)> what) {
    change([this, what = std::move(what)] { what(host_.simulation()); });
  };
  pick_and_drag_.begin_events(ui_wants_mouse);
  for (const InputEvent& event : events) {
    if (event.type != InputEvent::Type::key_press) {
      // A key before it in the list may have hidden the colliders.
      context.colliders_shown = panel_.colliders;
      context.camera_only = right_.student();
      pick_and_drag_.mouse_event(event, context);
    } else if (!ui_wants_keyboard) {
      apply(command_for_key(event.code, event.control));
    }
  }
}

void Viewer::save_scene() {
  const SavedScene saved_scene =
      save_and_record_.save_scene(scene_, host_.simulation(), view_camera_.camera());
  // The picker offers it from now on, under its own name.
  const std::string& path = saved_scene.path;
  if (!path.empty() &&
      std::find(scene_sources_.begin(), scene_sources_.end(), path) == scene_sources_.end()) {
    scene_sources_.push_back(path);
    scene_labels_.push_back(scene_label(path));
  }
  saved(saved_scene.message);
}

void Viewer::apply(ViewerCommand command) {
  if (save_and_record_.command(command)) return;
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
        pick_and_drag_.cancel_drags();  // reset puts the colliders back
        host_.simulation().reset();
        right_.reset(scene_, host_.simulation());
        instruments_.clear();
        host_.restart_drag_script();
        step_warning_.clear();
      });
      break;
    case ViewerCommand::toggle_split:
      right_.ask_split(!right_.split_asked());
      change([this] { apply_split_settings(); });
      break;
    case ViewerCommand::toggle_plots:
      instruments_.toggle_both();
      change([this] { update_recording(); });
      break;
    case ViewerCommand::toggle_wireframe:
      panel_.wireframe = !panel_.wireframe;
      break;
    case ViewerCommand::toggle_wind:
      change([this] {
        SimulationParams wanted = host_.simulation().params();
        toggle(*find_setting("wind"), wanted);
        host_.simulation().apply(wanted);
        show_environment_in_panel();
      });
      break;
    case ViewerCommand::toggle_colliders:
      panel_.colliders = !panel_.colliders;
      if (!panel_.colliders) pick_and_drag_.drop_collider();
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
      view_camera_.frame_shape();
      break;
    case ViewerCommand::default_view:
      view_camera_.restore_opening_view();
      break;
    case ViewerCommand::quit:
      quit_ = true;
      break;
    case ViewerCommand::toggle_panel:
      show_panel_ = !show_panel_;
      break;
    case ViewerCommand::export_obj:
      // The state the user sees, once a running batch finished.
      change([this] { saved(save_and_record_.export_obj(scene_, host_.simulation())); });
      break;
    case ViewerCommand::save_scene:
      change([this] { save_scene(); });  // the settings of the state drawn
      break;
    case ViewerCommand::screenshot:  // SaveAndRecord's
    case ViewerCommand::toggle_record:
      break;
    case ViewerCommand::close_overlays:
      panel_.show_help = false;
      break;
    case ViewerCommand::none:
      break;
  }
}

}  // namespace wobble

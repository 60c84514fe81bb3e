// The viewer's mouse and keys: what each event does to the camera, the pins and the playback.
#include "app/viewer/viewer.h"
#include "sim/settings/setting_registry.h"

namespace wobble {

void Viewer::handle_events(const std::vector<InputEvent>& events, bool ui_wants_mouse,
                           bool ui_wants_keyboard, const Eigen::Vector2f& window_size) {
  // The simulation a change edits is the one there when the change is made, not as now.
  PointerContext context{drawing_.pointer_view(window_size, panel_state_.place(), split()),
                         drawing_.view_camera(), host_.simulation()};
  // The simulation a change edits is the one there when the change is made, not as now.
  context.change = [this](std::function<void(Simulation&)> what) {
    change([this, what = std::move(what)] { what(host_.simulation()); });
  };
  pick_and_drag_.begin_events(ui_wants_mouse);
  for (const InputEvent& event : events) {
    if (event.type != InputEvent::Type::key_press) {
      // A key before it in the list may have hidden the colliders.
      context.colliders_shown = panel_.colliders;
      context.camera_only = session_.right().student();
      pick_and_drag_.mouse_event(event, context);
    } else if (!ui_wants_keyboard) {
      apply(command_for_key(event.code, event.control));
    }
  }
}

void Viewer::save_scene() {
  const SavedScene saved_scene =
      files_.saves().save_scene(scene_, host_.simulation(), drawing_.camera());
  // The picker offers it from now on, under its own name.
  session_.offer(saved_scene.path);
  saved(saved_scene.message);
}

void Viewer::apply(ViewerCommand command) {
  if (files_.saves().command(command)) return;
  if (panel_state_.command(command)) return;
  switch (command) {
    case ViewerCommand::step_once:
      panel_.paused = true;
      session_.ask_one_step();
      break;
    case ViewerCommand::reset:
      change([this] {
        pick_and_drag_.cancel_drags();  // reset puts the colliders back
        host_.simulation().reset();
        session_.right().reset(scene_, host_.simulation());
        session_.after_reset();
      });
      break;
    case ViewerCommand::toggle_split:
      session_.right().ask_split(!session_.right().split_asked());
      change([this] { apply_split_settings(); });
      break;
    case ViewerCommand::toggle_plots:
      session_.plots().toggle_both();
      change([this] { session_.update_recording(); });
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
    case ViewerCommand::frame_mesh:
      drawing_.view_camera().frame_shape();
      break;
    case ViewerCommand::default_view:
      drawing_.view_camera().restore_opening_view();
      break;
    case ViewerCommand::export_obj:
      // The state the user sees, once a running batch finished.
      change([this] { saved(files_.saves().export_obj(scene_, host_.simulation())); });
      break;
    case ViewerCommand::save_scene:
      change([this] { save_scene(); });  // the settings of the state drawn
      break;
    default:  // the panel's and SaveAndRecord's, taken above
      break;
  }
}

}  // namespace wobble

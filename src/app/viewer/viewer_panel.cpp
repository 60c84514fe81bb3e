#include "app/viewer/viewer_panel.h"

#include <imgui.h>

#include <utility>

namespace wobble {

ViewerPanel::ViewerPanel(const ViewLayers& layers, ColorQuantity color_by,
                         std::vector<Binding> help, PageActions page, bool folded)
    : folded_(folded), help_(std::move(help)), page_(std::move(page)) {
  settings_.surface = layers.surface;
  settings_.wireframe = layers.wireframe;
  settings_.springs = layers.springs;
  settings_.points = layers.points;
  settings_.ground = layers.ground;
  settings_.color_by = static_cast<int>(color_by);
  settings_.page = static_cast<bool>(page_.pick_files);
}

ViewLayers ViewerPanel::layers() const {
  ViewLayers layers;
  layers.surface = settings_.surface;
  layers.wireframe = settings_.wireframe;
  layers.springs = settings_.springs;
  layers.points = settings_.points;
  layers.ground = settings_.ground;
  layers.solids = settings_.colliders;
  return layers;
}

bool ViewerPanel::command(ViewerCommand command) {
  switch (command) {
    case ViewerCommand::toggle_pause:
      settings_.paused = !settings_.paused;
      return true;
    case ViewerCommand::toggle_wireframe:
      settings_.wireframe = !settings_.wireframe;
      return true;
    case ViewerCommand::toggle_points:
      settings_.points = !settings_.points;
      return true;
    case ViewerCommand::toggle_springs:
      settings_.springs = !settings_.springs;
      return true;
    case ViewerCommand::cycle_color_by:
      settings_.color_by = static_cast<int>(next_color_quantity(color_by()));
      return true;
    case ViewerCommand::toggle_help:
      settings_.show_help = !settings_.show_help;
      return true;
    case ViewerCommand::quit:
      quit_ = true;
      return true;
    case ViewerCommand::toggle_panel:
      shown_ = !shown_;
      return true;
    case ViewerCommand::close_overlays:
      settings_.show_help = false;
      return true;
    default:
      return false;
  }
}

void ViewerPanel::show_shape(bool has_faces) {
  // Springs without faces (a chain, a net) draw no surface, so without their springs and
  // vertices the view would show only the pins: they are shown as the course's viewer shows
  // them, and the user can still turn them off. What was chosen for meshes with faces is kept
  // for the next one.
  if (!faceless_) {
    chosen_springs_ = settings_.springs;
    chosen_points_ = settings_.points;
  }
  faceless_ = !has_faces;
  settings_.springs = faceless_ || chosen_springs_;
  settings_.points = faceless_ || chosen_points_;
}

PanelRequests ViewerPanel::draw(PanelParts parts, const PanelStats& stats,
                                const std::vector<SceneChoice>& scenes,
                                const std::string& step_warning, float ui_scale) {
  PanelRequests requests;
  if (shown_) {
    // A phone's screen is narrower than the panel: it opens folded (its title bar; a tap opens
    // it), so that the scene shows. The panel is the first window begun this frame.
    if (folded_) ImGui::SetNextWindowCollapsed(true, ImGuiCond_Once);
    folded_ = false;
    parts.scene_rows = [&] {
      static_cast<SceneRowRequests&>(requests) = draw_scene_rows(settings_, scenes);
    };
    parts.play_rows = [&] {
      static_cast<PlayRequests&>(requests) = draw_play_rows(settings_, stats.warning);
    };
    parts.simulation = [&] {
      requests.restore_defaults = draw_simulation_section(settings_, stats.course_scene);
    };
    parts.environment = [&] { draw_environment_section(settings_, environment_offer(stats)); };
    parts.view = [&] { draw_view_section(settings_); };
    place_ = draw_control_panel(parts, stats, settings_.paused, ui_scale);
  } else {
    place_ = PanelPlace();  // a hidden panel covers nothing: F frames in the whole window
  }
  std::vector<std::pair<std::string, std::string>> help;
  for (const Binding& binding : help_)
    help.emplace_back(binding.input, binding.action);
  draw_help_overlay(help, settings_.show_help);
  draw_step_warning(step_warning, ui_scale);
  if (requests.pick_files && page_.pick_files) page_.pick_files();
  if (requests.copy_link && page_.copy_link) page_.copy_link();
  return requests;
}

}  // namespace wobble

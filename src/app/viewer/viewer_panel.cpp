// The viewer's side of the control panel: its parts, each drawn by what owns its settings, and
// what they changed, handed to the simulation.
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "app/cli/solver_choice.h"
#include "app/interaction/environment_controls.h"
#include "app/viewer/side_settings.h"
#include "app/viewer/viewer.h"

namespace wobble {

void Viewer::build_ui(const PanelStats& timings, float ui_scale) {
  PanelStats stats = this->stats();
  stats.show_timings = timings.show_timings;
  stats.fps = timings.fps;
  stats.ui_frame_ms = timings.ui_frame_ms;
  stats.real_time_factor = timings.real_time_factor;
  stats.steps_per_second = timings.steps_per_second;
  const StepTiming& step = last_timing_;
  stats.step_ms = step_ms_.median();
  stats.local_ms = local_ms_.median();
  stats.global_ms = global_ms_.median();
  stats.forces_ms = static_cast<float>(step.forces_ms);
  stats.instruments_ms = static_cast<float>(step.instruments_ms);
  stats.term_figures.clear();
  for (const wobble::TermFigure& figure : step.figures) {
    stats.term_figures.push_back(PanelStats::TermFigure{figure.term, figure.name, figure.unit,
                                                        static_cast<float>(figure.value)});
  }

  // The panel's UI scale (for projectors) multiplies the screen's. Text is a whole number of
  // pixels high, 13 times the scale rounded, as ImGuiSession draws the font at the screen's scale:
  // at that scale the font is drawn as it was made, each glyph on whole pixels (at a pixel ratio
  // of 1.25 a 16 px font magnified to 16.25 put every glyph's edge between two pixels), and only
  // a UI scale above it magnifies it.
  const float font_drawn =
      ImGui::GetIO().Fonts->Fonts.empty() ? 13.0f : ImGui::GetIO().Fonts->Fonts[0]->FontSize;
  ImGui::GetIO().FontGlobalScale = std::round(13.0f * ui_scale * panel_.ui_scale) / font_drawn;
  ui_scale *= panel_.ui_scale;
  // Each part of the panel is drawn by what owns its settings; what was pressed is carried out
  // below, in this order, once the panel is drawn.
  bool plots_csv = false;  // the instruments' CSV button
  PanelRequests requests;
  if (show_panel_) {
    PanelParts parts;
    parts.scene_rows = [&] {
      static_cast<SceneRowRequests&>(requests) = draw_scene_rows(panel_, scene_choices_);
    };
    parts.save_rows = [&] {
      static_cast<SaveRowRequests&>(requests) = save_and_record_.draw_panel_rows();
    };
    parts.play_rows = [&] {
      static_cast<PlayRequests&>(requests) = draw_play_rows(panel_, stats.warning);
    };
    parts.simulation = [&] {
      requests.restore_defaults = draw_simulation_section(panel_, stats.course_scene);
    };
    parts.environment = [&] { draw_environment_section(panel_, environment_offer(stats)); };
    parts.view = [&] { draw_view_section(panel_); };
    parts.instruments = [&] { plots_csv = instruments_.draw_panel_section(); };
    parts.compare = [&] { right_.draw_panel_section(); };
    panel_place_ = draw_control_panel(parts, stats, panel_.paused, ui_scale);
  } else {
    panel_place_ = PanelPlace();  // a hidden panel covers nothing: F frames in the whole window
  }
  std::vector<std::pair<std::string, std::string>> help;
  for (const Binding& binding : help_)
    help.emplace_back(binding.input, binding.action);
  draw_help_overlay(help, panel_.show_help);
  draw_step_warning(step_warning_, ui_scale);
  draw_overlays(ui_scale);
  if (show_notices_) {
    const float display = ImGui::GetIO().DisplaySize.x;
    const float right = instruments_left_ >= 0.0f ? instruments_left_ : display;
    // Beside the open panel where a notice fits there; else below the panel (folded to its
    // title bar, or as wide as a phone's screen), so that neither hides the other.
    const float panel_right = panel_place_.x + panel_place_.width;
    const bool beside = panel_place_.shown && right - panel_right >= 220.0f * ui_scale;
    const bool below = show_panel_ && !beside && panel_place_.height > 0.0f;
    notices_.draw(notice_clock(), beside ? panel_right : 0.0f, right, ui_scale,
                  below ? panel_place_.y + panel_place_.height : 0.0f);
  }

  // A new scene (or the same one afresh) waits for a running batch (see load).
  if (requests.scene_changed) {
    // A scene file that fails to load leaves the current scene running, the picker showing it.
    if (!open_file(scene_sources_[panel_.scene])) {
      panel_.scene =
          static_cast<int>(std::find(scene_labels_.begin(), scene_labels_.end(), scene_.name) -
                           scene_labels_.begin());
    }
    return;
  }
  if (!requests.open_path.empty()) {
    open_file(requests.open_path);
    return;
  }
  if (requests.pick_files && page_actions_.pick_files) page_actions_.pick_files();
  if (requests.copy_link && page_actions_.copy_link) page_actions_.copy_link();
  if (requests.restore_defaults) {
    restore_defaults();
    return;
  }
  // The sliders' values stay in the panel until the simulation takes them (hand_over_changes
  // applies them again after a batch).
  if (!host_.batch_started()) apply_panel_settings();
  if (requests.step_once) apply(ViewerCommand::step_once);
  if (requests.reset) apply(ViewerCommand::reset);
  if (requests.frame_mesh) apply(ViewerCommand::frame_mesh);
  if (requests.save_scene) apply(ViewerCommand::save_scene);
  if (requests.export_obj) apply(ViewerCommand::export_obj);
  if (plots_csv) {
    saved(save_and_record_.save_plots(scene_.name, instruments_.convergence_csv(),
                                      instruments_.energy_csv()));
  }
  if (requests.default_view) apply(ViewerCommand::default_view);
}

void Viewer::apply_panel_settings() {
  // The panel's settings as one settings value; Simulation::apply does what the difference needs
  // (k and dt a numeric re-factorization, another solver takes over from the next step, from the
  // state this one left), and nothing when there is none. The iterations slider reaches 100; a
  // mesh whose step would pass limits::max_step_work stops short.
  Simulation& simulation = host_.simulation();
  const SimulationParams& params = simulation.params();
  SimulationParams wanted =
      settings_from_sliders(params, panel_, simulation.max_iterations_for_mesh());
  // The slider is gravity's strength: the scene's direction stays, sideways part included.
  if (static_cast<float>(params.gravity.norm()) != panel_.gravity) {
    wanted.gravity = gravity_with_magnitude(scene_.params.gravity, panel_.gravity);
  }
  // The environment's controls, then shown again where the change did more than the control
  // (the wind turned on over a calm scene blows the breeze, whose speed the panel then shows).
  wanted = settings_from_sliders(wanted, panel_.environment, simulation.max_iterations_for_mesh());
  const bool new_dt = wanted.dt != params.dt, wind_switched = wanted.wind.on != params.wind.on;
  simulation.apply(wanted);
  if (new_dt) host_.restart_clock();
  if (wind_switched) show_environment_in_panel();
  apply_split_settings();
}

void Viewer::write_window_files(bool drawn, const std::function<RgbaImage()>& read_frame) {
  for (const std::string& what :
       save_and_record_.write_frame(scene_.name, shown_steps(), drawn, read_frame, shown_time()))
    saved(what);
}

FrameTime Viewer::shown_time() const {
  // While a batch runs, the simulation is the stepping thread's: the copy taken before it.
  const double seconds =
      host_.batch_started() ? shown_stats_.simulated_seconds : host_.simulation().time();
  const SettingControl* dt = panel_.control("dt");
  return FrameTime{seconds, dt ? static_cast<double>(dt->value) : host_.simulation().params().dt};
}

}  // namespace wobble

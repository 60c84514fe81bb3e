// The viewer's UI: the panel's parts, each drawn by the component that owns its settings, what
// they changed, handed to the simulation, and the notices.
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "app/viewer/side_settings.h"
#include "app/viewer/viewer.h"

namespace wobble {

void Viewer::build_ui(const PanelStats& timings, float ui_scale, bool whole_panel) {
  if (!whole_panel) {
    draw_overlays(ui_scale);
    return;
  }
  PanelStats stats = session_.stats();
  stats.show_timings = timings.show_timings;
  stats.fps = timings.fps;
  stats.ui_frame_ms = timings.ui_frame_ms;
  stats.real_time_factor = timings.real_time_factor;
  stats.steps_per_second = timings.steps_per_second;
  const PanelStats steps = session_.step_times();
  stats.step_ms = steps.step_ms;
  stats.local_ms = steps.local_ms;
  stats.global_ms = steps.global_ms;
  stats.forces_ms = steps.forces_ms;
  stats.instruments_ms = steps.instruments_ms;
  stats.term_figures = steps.term_figures;

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
  SaveRowRequests saves;
  PanelParts parts;
  parts.save_rows = [&] { saves = files_.saves().draw_panel_rows(); };
  parts.instruments = [&] { plots_csv = session_.plots().draw_panel_section(); };
  parts.compare = [&] { session_.right().draw_panel_section(); };
  PanelRequests requests =
      panel_state_.draw(parts, stats, session_.scene_choices(), session_.step_warning(), ui_scale);
  static_cast<SaveRowRequests&>(requests) = saves;
  draw_overlays(ui_scale);
  if (files_.notices_shown()) {
    const PanelPlace place = panel_state_.place();
    const float display = ImGui::GetIO().DisplaySize.x;
    const float plots_left = drawing_.plots_left();
    const float right = plots_left >= 0.0f ? plots_left : display;
    // Beside the open panel where a notice fits there; else below the panel (folded to its
    // title bar, or as wide as a phone's screen), so that neither hides the other.
    const float panel_right = place.x + place.width;
    const bool beside = place.shown && right - panel_right >= 220.0f * ui_scale;
    const bool below = panel_state_.shown() && !beside && place.height > 0.0f;
    files_.notices().draw(notice_clock(), beside ? panel_right : 0.0f, right, ui_scale,
                          below ? place.y + place.height : 0.0f);
  }

  // A new scene (or the same one afresh) waits for a running batch (see load).
  if (requests.scene_changed) {
    // A scene file that fails to load leaves the current scene running, the picker showing it.
    if (!files_.open_file(session_.scene_sources()[panel_.scene])) {
      panel_.scene = session_.scene_index();
    }
    return;
  }
  if (!requests.open_path.empty()) {
    files_.open_file(requests.open_path);
    return;
  }
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
    saved(files_.saves().save_plots(scene_.name, session_.instruments().convergence_csv(),
                                    session_.instruments().energy_csv()));
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
  // The environment's controls, then shown again where the change did more than the control
  // (the wind turned on over a calm scene blows the breeze, whose speed the panel then shows).
  wanted = settings_from_sliders(wanted, panel_.environment, simulation.max_iterations_for_mesh());
  const bool new_dt = wanted.dt != params.dt, wind_switched = wanted.wind.on != params.wind.on;
  simulation.apply(wanted);
  if (new_dt) host_.restart_clock();
  if (wind_switched) show_environment_in_panel();
  apply_split_settings();
}

}  // namespace wobble

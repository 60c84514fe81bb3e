#include "control_panel.h"

#include <imgui.h>

#include <algorithm>

#include "log_drag.h"
#include "panel_stats.h"

namespace wobble {

namespace {

const ImVec4 warning_color(1.0f, 0.75f, 0.2f, 1.0f);

// A section of the panel that opens and closes; open at first unless told.
bool section(const char* title, bool open_at_first = true) {
  return ImGui::CollapsingHeader(title, open_at_first ? ImGuiTreeNodeFlags_DefaultOpen : 0);
}

// Ends the scrolling sections. A section closed near the bottom of a list scrolled down would
// leave the list shorter than where it is scrolled to, and ImGui would clamp the scroll, so that
// every header moved under the mouse: a blank at the end, only as tall as that needs, keeps the
// scroll where it is. It shrinks as the user scrolls back up.
void hold_scroll() {
  const float scroll = ImGui::GetScrollY();
  const float short_by = scroll + ImGui::GetWindowHeight() - ImGui::GetCursorPosY();
  if (scroll > 0.0f && short_by > 0.0f) ImGui::Dummy(ImVec2(1.0f, short_by));
}

// The file row, the play row and what the simulation says about itself.
void draw_top_rows(PanelSettings& settings, const PanelStats& stats,
                   const std::vector<std::string>& scene_names, PanelRequests& requests) {
  if (!scene_names.empty()) {
    const char* current = scene_names[settings.scene].c_str();
    if (ImGui::BeginCombo("scene", current)) {
      for (int i = 0; i < static_cast<int>(scene_names.size()); ++i) {
        // Choosing the current scene again opens it afresh, with its own settings.
        if (ImGui::Selectable(scene_names[i].c_str(), i == settings.scene)) {
          settings.scene = i;
          requests.scene_changed = true;
        }
      }
      ImGui::EndCombo();
    }
  }

  // A scene or mesh file by path (or dropped on the window): Enter or the button opens it.
  const bool entered =
      ImGui::InputTextWithHint("##open", "scene or mesh file path", settings.open_path,
                               sizeof(settings.open_path), ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if ((ImGui::Button("Open") || entered) && settings.open_path[0] != '\0') {
    requests.open_path = settings.open_path;
  }
  // Files into the working folder, each under the next free number.
  requests.save_scene = ImGui::Button("Save scene");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Ctrl+S: the scene with its pins and settings as wobble-SCENE-scene-0001.json\n"
        "and its mesh beside it; wobble opens it as it is now (from rest)");
  }
  ImGui::SameLine();
  requests.export_obj = ImGui::Button("OBJ");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("F11: the current positions as wobble-SCENE-0001.obj");
  ImGui::SameLine();
  requests.screenshot = ImGui::Button("PNG");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("F12: the window as wobble-SCENE-0001.png");
  ImGui::SameLine();
  ImGui::Checkbox("record", &settings.recording);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "F9: every new state drawn as DIR/frame_00001.png, ...\n"
        "into a new folder wobble-SCENE-frames-0001");
  }
  if (!stats.recording.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.35f, 0.3f, 1.0f));
    ImGui::TextWrapped("recording to %s", stats.recording.c_str());
    ImGui::PopStyleColor();
  }

  if (ImGui::Button(settings.paused ? "Play" : "Pause")) settings.paused = !settings.paused;
  ImGui::SameLine();
  requests.step_once = ImGui::Button("Step");
  ImGui::SameLine();
  requests.reset = ImGui::Button("Reset");
  ImGui::SameLine();
  requests.frame_mesh = ImGui::Button("Frame");
  ImGui::SameLine();
  requests.default_view = ImGui::Button("View");
  ImGui::SameLine();
  if (ImGui::Button("Help")) settings.show_help = !settings.show_help;
  ImGui::Checkbox("real time", &settings.real_time);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "On: as many steps before each frame as keep the motion at its true speed,\n"
        "as far as they fit in a frame (a slower step shows slow motion).\n"
        "Off: one step a frame.");
  }
  if (!stats.warning.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, warning_color);
    ImGui::TextWrapped("%s", stats.warning.c_str());
    ImGui::PopStyleColor();
  }
}

// The tooltip of every drag over decades.
void log_drag_tooltip() {
  if (ImGui::IsItemHovered() && !ImGui::IsItemActive()) {
    ImGui::SetTooltip(
        "Drag: 1%% a pixel (Shift: 10%%, Alt: finer)\n"
        "Ctrl+click or double-click: type a value");
  }
}

void draw_simulation_section(PanelSettings& settings, const PanelStats& stats,
                             PanelRequests& requests) {
  // Stiffness spans six decades and dt four: both move by a factor a pixel (log_drag.h).
  log_drag("k (N/m)", &settings.k, PanelSettings::min_k, PanelSettings::max_k, "%.1f");
  log_drag_tooltip();
  log_drag("dt (s)", &settings.dt, PanelSettings::min_dt, PanelSettings::max_dt, "%.5f");
  log_drag_tooltip();
  ImGui::SliderInt("iterations", &settings.iterations, PanelSettings::min_iterations,
                   PanelSettings::max_iterations, "%d", ImGuiSliderFlags_AlwaysClamp);
  // A course scene reproduces the course's program, which iterates plainly.
  if (stats.course_scene) ImGui::BeginDisabled();
  ImGui::Checkbox("Chebyshev acceleration", &settings.chebyshev);
  if (stats.course_scene) {
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
      ImGui::SetTooltip(
          "A course scene reproduces the course's program exactly:\n"
          "plain iterations only.");
    }
  }
  ImGui::SliderFloat("gravity (m/s^2)", &settings.gravity, 0.0f, PanelSettings::max_gravity, "%.2f",
                     ImGuiSliderFlags_AlwaysClamp);
  requests.restore_defaults = ImGui::Button("Restore defaults");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("The scene as it opened: its settings, pins, colliders and start");
  }
}

void draw_environment_section(PanelSettings& settings, const PanelStats& stats) {
  // Damping from a hundredth to ten per second: by a factor a pixel too.
  log_drag("damping (1/s)", &settings.damping, 0.0f, PanelSettings::max_damping, "%.3f");
  log_drag_tooltip();
  if (stats.has_colliders) {
    ImGui::SliderFloat("friction", &settings.friction, 0.0f, PanelSettings::max_friction, "%.2f",
                       ImGuiSliderFlags_AlwaysClamp);
  }
  ImGui::Checkbox("wind (W)", &settings.wind);
  if (stats.aerodynamic_wind) {
    ImGui::SliderFloat("wind (m/s)", &settings.wind_speed, 0.0f, PanelSettings::max_wind_speed,
                       "%.1f", ImGuiSliderFlags_AlwaysClamp);
    ImGui::SliderFloat("wind heading", &settings.wind_heading, 0.0f, 360.0f, "%.0f deg",
                       ImGuiSliderFlags_AlwaysClamp);
  }
  if (stats.has_colliders) ImGui::Checkbox("colliders", &settings.colliders);
  // A course scene reproduces the course's program, which has no self-collision: not offered.
  if (!stats.course_scene) {
    ImGui::Checkbox("self-collision", &settings.self_collision);
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("Keep the surface from passing through itself, a thickness apart");
    }
    if (settings.self_collision) {
      log_drag("thickness (mm)", &settings.self_collision_mm, PanelSettings::min_self_collision_mm,
               PanelSettings::max_self_collision_mm, "%.2f");
      log_drag_tooltip();
    }
  }
}

void draw_view_section(PanelSettings& settings) {
  ImGui::Checkbox("surface", &settings.surface);
  ImGui::SameLine();
  ImGui::Checkbox("wireframe", &settings.wireframe);
  ImGui::SameLine();
  ImGui::Checkbox("ground", &settings.ground);
  ImGui::Checkbox("springs", &settings.springs);
  ImGui::SameLine();
  ImGui::Checkbox("points", &settings.points);
  const char* const color_names[] = {"material", "strain", "speed", "contacts"};
  ImGui::Combo("colour by", &settings.color_by, color_names, IM_ARRAYSIZE(color_names));
  ImGui::SliderFloat("UI scale", &settings.ui_scale, PanelSettings::min_ui_scale,
                     PanelSettings::max_ui_scale, "%.2f", ImGuiSliderFlags_AlwaysClamp);
}

void draw_compare_section(PanelSettings& settings, const PanelStats& stats) {
  if (stats.student_side) {
    // wobble --student: the right side is the student's step, with the seed's settings.
    ImGui::TextWrapped(
        "right: the student's fast_mass_springs_step_sparse, coloured by its "
        "distance from Wobble's (left)");
    return;
  }
  ImGui::Checkbox("split view: right side", &settings.split);
  if (!settings.split) return;
  log_drag("k right", &settings.right_k, PanelSettings::min_k, PanelSettings::max_k, "%.1f");
  log_drag_tooltip();
  log_drag("dt right", &settings.right_dt, PanelSettings::min_dt, PanelSettings::max_dt, "%.5f");
  log_drag_tooltip();
  ImGui::SliderInt("iterations right", &settings.right_iterations, PanelSettings::min_iterations,
                   PanelSettings::max_iterations, "%d", ImGuiSliderFlags_AlwaysClamp);
  ImGui::Checkbox("Chebyshev right", &settings.right_chebyshev);
}

}  // namespace

PanelRequests draw_control_panel(PanelSettings& settings, const PanelStats& stats,
                                 const std::vector<std::string>& scene_names, float ui_scale) {
  PanelRequests requests;
  const ImGuiStyle& style = ImGui::GetStyle();
  ImGui::SetNextWindowPos(ImVec2(10.0f * ui_scale, 10.0f * ui_scale), ImGuiCond_FirstUseEver);
  // A fixed width, since its widgets take the window's width; as tall as its contents, never
  // taller than the display. Where the display is shorter, the sections scroll in a list of
  // their own and the stats stay pinned under it.
  const float width = 330.0f * ui_scale;
  const float tallest =
      std::max(ImGui::GetIO().DisplaySize.y - 20.0f * ui_scale, 100.0f * ui_scale);
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, tallest));
  // Begin returns false when the panel is collapsed to its title bar, which covers next to
  // nothing: the view is then framed as if there were no panel.
  requests.place.shown =
      ImGui::Begin("Wobble", nullptr,
                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoScrollbar |
                       ImGuiWindowFlags_NoScrollWithMouse);
  const ImVec2 position = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  requests.place.x = position.x;
  requests.place.y = position.y;
  requests.place.width = size.x;
  requests.place.height = size.y;
  if (!requests.place.shown) {
    ImGui::End();
    return requests;
  }

  // The list is as tall as its contents were last frame, or as what the panel leaves it.
  const float stats_height =
      static_cast<float>(panel_stats_lines(stats)) * ImGui::GetTextLineHeightWithSpacing();
  const float list_room = tallest - ImGui::GetCursorPosY() - style.WindowPadding.y -
                          2.0f * style.ItemSpacing.y - stats_height - 1.0f;
  ImGuiStorage* storage = ImGui::GetStateStorage();
  const ImGuiID list_height_id = ImGui::GetID("##sections height");
  const float list_height =
      std::max(std::min(storage->GetFloat(list_height_id, list_room), list_room), 40.0f * ui_scale);
  ImGui::BeginChild("sections", ImVec2(0.0f, list_height));
  // Widgets take what the labels leave.
  ImGui::PushItemWidth(-120.0f * ui_scale);
  draw_top_rows(settings, stats, scene_names, requests);
  if (section("simulation")) draw_simulation_section(settings, stats, requests);
  if (section("environment")) draw_environment_section(settings, stats);
  if (section("view")) draw_view_section(settings);
  if (section("instruments")) {
    ImGui::Checkbox("convergence", &settings.show_convergence);
    ImGui::SameLine();
    ImGui::Checkbox("energy", &settings.show_energy);
  }
  if (section("compare")) draw_compare_section(settings, stats);
  if (stats.show_timings && section("timings", false)) draw_panel_timings(stats);
  if (!stats.notes.empty() && section("scene notes")) {
    for (const std::string& note : stats.notes)
      ImGui::TextWrapped("%s", note.c_str());
  }
  ImGui::PopItemWidth();
  hold_scroll();
  const float contents = ImGui::GetCursorPosY();
  ImGui::EndChild();
  storage->SetFloat(list_height_id, contents);

  ImGui::Separator();
  ImGui::BeginChild("stats", ImVec2(0.0f, stats_height), false,
                    ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  draw_panel_stats(stats, settings.paused);
  ImGui::EndChild();
  ImGui::End();
  return requests;
}

void draw_help_overlay(const std::vector<std::pair<std::string, std::string>>& bindings,
                       bool& open) {
  if (!open) return;
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0.5f * io.DisplaySize.x, 0.5f * io.DisplaySize.y),
                          ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(0.9f);
  ImGui::Begin("Keys and mouse", &open,
               ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings);
  if (ImGui::BeginTable("bindings", 2, ImGuiTableFlags_RowBg)) {
    for (const auto& [input, action] : bindings) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(input.c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(action.c_str());
    }
    ImGui::EndTable();
  }
  ImGui::End();
}

void draw_step_warning(const std::string& warning, float ui_scale) {
  if (warning.empty()) return;
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0.5f * io.DisplaySize.x, 10.0f * ui_scale), ImGuiCond_Always,
                          ImVec2(0.5f, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(std::min(460.0f * ui_scale, io.DisplaySize.x - 20.0f), 0.0f),
                           ImGuiCond_Always);
  ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.35f, 0.08f, 0.05f, 0.92f));
  ImGui::Begin("Simulation paused", nullptr,
               ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
  ImGui::TextWrapped("%s", warning.c_str());
  ImGui::TextDisabled("Change dt or iterations in the panel, then Play or Reset.");
  ImGui::End();
  ImGui::PopStyleColor();
}

}  // namespace wobble

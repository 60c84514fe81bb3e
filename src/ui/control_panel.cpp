#include "control_panel.h"

#include <imgui.h>

#include <algorithm>

namespace wobble {

namespace {

// Rows of label and value, aligned.
void stat_row(const char* label, const char* format, double value) {
  ImGui::TextUnformatted(label);
  ImGui::SameLine(110.0f * ImGui::GetIO().FontGlobalScale);
  ImGui::Text(format, value);
}

// A titled divider (ImGui 1.86 has no SeparatorText).
void section(const char* title) {
  ImGui::Spacing();
  ImGui::Separator();
  ImGui::TextDisabled("%s", title);
}

const ImVec4 warning_color(1.0f, 0.75f, 0.2f, 1.0f);

// Whether the motion on screen is the simulation's own speed: it runs in slow motion when the
// steps take longer than they simulate (or, without real time, when a frame does).
void real_time_rows(const PanelStats& stats, bool paused) {
  ImGui::TextUnformatted("real time");
  ImGui::SameLine(110.0f * ImGui::GetIO().FontGlobalScale);
  if (paused) {
    ImGui::TextUnformatted("paused");
    return;
  }
  const bool slow = stats.real_time_factor < 0.95f;
  // "\xc3\x97" is U+00D7, the multiplication sign: in the default font's Latin-1 range.
  ImGui::Text("\xc3\x97%.2f%s", stats.real_time_factor, slow ? " (slow motion)" : "");
  stat_row("steps", "%.0f /s", stats.steps_per_second);
}

}  // namespace

PanelRequests draw_control_panel(PanelSettings& settings, const PanelStats& stats,
                                 const std::vector<std::string>& scene_names, float ui_scale) {
  PanelRequests requests;
  ImGui::SetNextWindowPos(ImVec2(10.0f * ui_scale, 10.0f * ui_scale), ImGuiCond_FirstUseEver);
  // As tall as its contents (a warning or the split view's rows add to it), never taller than
  // the display, where it scrolls; a fixed width, since its widgets take the window's width.
  const float width = 330.0f * ui_scale;
  ImGui::SetNextWindowSizeConstraints(
      ImVec2(width, 0.0f),
      ImVec2(width, std::max(ImGui::GetIO().DisplaySize.y - 20.0f * ui_scale, 100.0f * ui_scale)));
  // Begin returns false when the panel is collapsed to its title bar, which covers next to
  // nothing: the view is then framed as if there were no panel.
  requests.place.shown = ImGui::Begin("Wobble", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  const ImVec2 position = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  requests.place.x = position.x;
  requests.place.y = position.y;
  requests.place.width = size.x;
  requests.place.height = size.y;
  // Widgets take what the labels leave.
  ImGui::PushItemWidth(-120.0f * ui_scale);

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

  section("simulation");
  // Stiffness spans six decades, so its slider is logarithmic.
  ImGui::SliderFloat("k (N/m)", &settings.k, PanelSettings::min_k, PanelSettings::max_k, "%.1f",
                     ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
  ImGui::SliderFloat("dt (s)", &settings.dt, PanelSettings::min_dt, PanelSettings::max_dt, "%.4f",
                     ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
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

  section("environment");
  ImGui::SliderFloat("damping (1/s)", &settings.damping, 0.0f, PanelSettings::max_damping, "%.2f",
                     ImGuiSliderFlags_AlwaysClamp);
  if (stats.has_colliders) {
    ImGui::SliderFloat("friction", &settings.friction, 0.0f, PanelSettings::max_friction, "%.2f",
                       ImGuiSliderFlags_AlwaysClamp);
  }
  ImGui::Checkbox("wind", &settings.wind);
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
      ImGui::SliderFloat("thickness (mm)", &settings.self_collision_mm,
                         PanelSettings::min_self_collision_mm, PanelSettings::max_self_collision_mm,
                         "%.2f", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    }
  }

  section("view");
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

  section("instruments");
  ImGui::Checkbox("convergence", &settings.show_convergence);
  ImGui::SameLine();
  ImGui::Checkbox("energy", &settings.show_energy);

  section("compare");
  if (stats.student_side) {
    // wobble --student: the right side is the student's step, with the seed's settings.
    ImGui::TextWrapped(
        "right: the student's fast_mass_springs_step_sparse, coloured by its "
        "distance from Wobble's (left)");
  } else {
    ImGui::Checkbox("split view: right side", &settings.split);
  }
  if (settings.split && !stats.student_side) {
    ImGui::SliderFloat("k right", &settings.right_k, PanelSettings::min_k, PanelSettings::max_k,
                       "%.1f", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    ImGui::SliderFloat("dt right", &settings.right_dt, PanelSettings::min_dt, PanelSettings::max_dt,
                       "%.4f", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    ImGui::SliderInt("iterations right", &settings.right_iterations, PanelSettings::min_iterations,
                     PanelSettings::max_iterations, "%d", ImGuiSliderFlags_AlwaysClamp);
    ImGui::Checkbox("Chebyshev right", &settings.right_chebyshev);
  }

  section("stats");
  if (stats.show_timings) {
    // Frames come when there is something new to draw; each takes the UI this long, steps apart.
    ImGui::TextUnformatted("fps");
    ImGui::SameLine(110.0f * ImGui::GetIO().FontGlobalScale);
    ImGui::Text("%.1f (a frame %.1f ms)", stats.fps, stats.ui_frame_ms);
    real_time_rows(stats, settings.paused);
    stat_row("step", "%.2f ms", stats.step_ms);
    stat_row("  local", "%.2f ms", stats.local_ms);
    stat_row("  global", "%.2f ms", stats.global_ms);
    if (stats.forces_ms > 0.0f) stat_row("  wind", "%.2f ms", stats.forces_ms);
    if (stats.instruments_ms > 0.0f) stat_row("  plots", "%.2f ms", stats.instruments_ms);
    if (stats.has_colliders) stat_row("  contact", "%.2f ms", stats.contact_ms);
    // With the timings: the count depends on the machine, and headless images must not.
    stat_row("threads", "%.0f", stats.threads);
  } else {
    ImGui::TextDisabled("timings hidden (headless)");
  }
  stat_row("simulated", "%.2f s", stats.simulated_seconds);
  stat_row("vertices", "%.0f", stats.vertices);
  stat_row("springs", "%.0f", stats.springs);
  stat_row("pins", "%.0f", stats.pins);
  if (stats.has_colliders) stat_row("contacts", "%.0f", stats.contacts);
  if (stats.self_collision) {
    ImGui::TextUnformatted("self contacts");
    ImGui::SameLine(110.0f * ImGui::GetIO().FontGlobalScale);
    if (stats.show_timings) {
      ImGui::Text("%d (detect %.2f ms, respond %.2f ms)", stats.self_contacts,
                  stats.self_detection_ms, stats.self_response_ms);
    } else {
      ImGui::Text("%d", stats.self_contacts);
    }
  }
  for (const std::string& note : stats.notes)
    ImGui::TextWrapped("%s", note.c_str());
  ImGui::PopItemWidth();
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

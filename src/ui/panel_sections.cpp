#include "panel_sections.h"

#include <imgui.h>

#include <algorithm>

#include "log_drag.h"

namespace wobble {

namespace {

// A scene's description as a tooltip, wrapped at about 40 characters of the font: one line of a
// long description ran 800 pixels across the plots beside the panel.
void wrapped_tooltip(const std::string& text) {
  ImGui::BeginTooltip();
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 24.0f);
  ImGui::TextUnformatted(text.c_str());
  ImGui::PopTextWrapPos();
  ImGui::EndTooltip();
}

const ImVec4 warning_color(1.0f, 0.75f, 0.2f, 1.0f);

// The tooltip of every drag over decades.
void log_drag_tooltip() {
  if (ImGui::IsItemHovered() && !ImGui::IsItemActive()) {
    ImGui::SetTooltip(
        "Drag: 1%% a pixel (Shift: 10%%, Alt: finer)\n"
        "Ctrl+click or double-click: type a value");
  }
}

}  // namespace

SceneRowRequests draw_scene_rows(SceneRowSettings& settings,
                                 const std::vector<SceneChoice>& scenes) {
  SceneRowRequests requests;
  if (!scenes.empty()) {
    const int count = static_cast<int>(scenes.size());
    settings.scene = std::clamp(settings.scene, 0, count - 1);
    const char* current = scenes[settings.scene].name.c_str();
    if (ImGui::BeginCombo("scene", current, ImGuiComboFlags_HeightLarge)) {
      // Wobble's scenes, then the course's under a heading; each says what it shows.
      for (const bool course : {false, true}) {
        bool heading = !course;
        for (int i = 0; i < count; ++i) {
          if (scenes[i].course != course) continue;
          if (!heading) {
            ImGui::Separator();
            ImGui::TextDisabled("the course's scenes");
            heading = true;
          }
          // Choosing the current scene again opens it afresh, with its own settings.
          if (ImGui::Selectable(scenes[i].name.c_str(), i == settings.scene)) {
            settings.scene = i;
            requests.scene_changed = true;
          }
          if (!scenes[i].description.empty() && ImGui::IsItemHovered())
            wrapped_tooltip(scenes[i].description);
        }
      }
      ImGui::EndCombo();
    }
    if (!scenes[settings.scene].description.empty() && ImGui::IsItemHovered())
      wrapped_tooltip(scenes[settings.scene].description);
  }
  if (settings.page) {
    requests.pick_files = ImGui::Button("Open file...");
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip(
          "A scene (.json) with its mesh, or a mesh (.obj, .mesh, .node, .ele);\n"
          "or drop the files onto the page");
    }
    ImGui::SameLine();
    requests.copy_link = ImGui::Button("Copy link");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("An address that opens this scene with its current settings");
    return requests;
  }
  // A scene or mesh file by path (or dropped on the window): Enter or the button opens it.
  const bool entered =
      ImGui::InputTextWithHint("##open", "scene or mesh file path", settings.open_path,
                               sizeof(settings.open_path), ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if ((ImGui::Button("Open") || entered) && settings.open_path[0] != '\0') {
    requests.open_path = settings.open_path;
  }
  return requests;
}

SaveRowRequests draw_save_rows(bool& recording, int& record_format, bool& record_whole_window,
                               const std::string& recording_status, bool offer_record) {
  SaveRowRequests requests;
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
  if (!offer_record) return requests;
  ImGui::SameLine();
  ImGui::Checkbox("record", &recording);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "F9: every new state drawn, as the combo beside says:\n"
        "PNG frames: DIR/frame_00001.png, ... in a new folder wobble-SCENE-frames-0001\n"
        "WebM video: wobble-SCENE-0001.webm (VP9; plays in every browser)\n"
        "MP4 video: wobble-SCENE-0001.mp4 (H.264; slides and players)\n"
        "scene only (the default): the 3-D view alone, for slides; whole window: the panel too\n"
        "A video's frames play at their simulated time.");
  }
  // Short names in the row, the full ones in the list; beside the toggle where it fits.
  static const char* const shown[] = {"PNG", "WebM", "MP4"};
  static const char* const listed[] = {"PNG frames", "WebM video", "MP4 video"};
  const ImGuiStyle& style = ImGui::GetStyle();
  const float combo_width =
      ImGui::CalcTextSize("WebM").x + ImGui::GetFrameHeight() + 2.0f * style.FramePadding.x;
  ImGui::SameLine();
  if (ImGui::GetContentRegionAvail().x < combo_width) ImGui::NewLine();
  ImGui::SetNextItemWidth(combo_width);
  record_format = std::clamp(record_format, 0, 2);
  ImGui::BeginDisabled(recording);  // one recording, one format
  // One combo for both choices, so that the row keeps its width: what record writes, then what a
  // frame shows, the scene alone (the default, what goes on a slide) or the whole window.
  if (ImGui::BeginCombo("##record as", shown[record_format])) {
    for (int format = 0; format < 3; ++format) {
      if (ImGui::Selectable(listed[format], format == record_format)) record_format = format;
    }
    ImGui::Separator();
    if (ImGui::Selectable("scene only", !record_whole_window)) record_whole_window = false;
    if (ImGui::Selectable("whole window", record_whole_window)) record_whole_window = true;
    ImGui::EndCombo();
  }
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
    ImGui::SetTooltip(
        "what record writes (PNG frames, a WebM or an MP4 video) and films: %s",
        record_whole_window ? "the whole window, panel included" : "the scene alone, for slides");
  }
  if (!recording_status.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.35f, 0.3f, 1.0f));
    ImGui::TextWrapped("recording to %s", recording_status.c_str());
    ImGui::PopStyleColor();
  }
  return requests;
}

PlayRequests draw_play_rows(PlaySettings& settings, const std::string& warning) {
  PlayRequests requests;
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
  if (!warning.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, warning_color);
    ImGui::TextWrapped("%s", warning.c_str());
    ImGui::PopStyleColor();
  }
  return requests;
}

namespace {

// Every number in the panel is dragged, by a step a pixel, as k and dt are (log_drag.h), never
// set by where a click lands: a click on a slider made the value jump there. Iterations move by
// one every five pixels; Ctrl+click types a value.
constexpr float drag_speed_iterations = 0.2f;

// A side's controls (`course_scene`: those a course keeps greyed out), each label followed by
// `suffix` (" right" for the right side).
void draw_setting_controls(std::vector<SettingControl>& controls, const char* suffix,
                           bool course_scene) {
  for (SettingControl& control : controls) {
    if (!control.shown) continue;
    if (!control.shown_with.empty()) {
      const SettingControl* with = nullptr;
      for (const SettingControl& other : controls) {
        if (other.name == control.shown_with) with = &other;
      }
      if (with && !with->on) continue;
    }
    if (control.kind == SettingControl::Kind::choice && control.choices.empty()) continue;
    const std::string label =
        control.label + (control.unit.empty() ? "" : " (" + control.unit + ")") + suffix;
    // Greyed out in a course scene, which reproduces the course's program, or where another
    // control's choice leaves it nothing to do.
    std::string why;
    if (course_scene && control.course_locked) {
      why =
          "A course scene reproduces the course's program exactly:\n"
          "plain local-global iterations, no damping, friction or self-collision.";
    } else if (!control.applies_with.empty()) {
      const SettingControl* with = nullptr;
      for (const SettingControl& other : controls) {
        if (other.name == control.applies_with) with = &other;
      }
      const bool applies = !with || with->choices.empty() || with->whole < 0 ||
                           with->whole >= static_cast<int>(control.applies_for.size()) ||
                           control.applies_for[with->whole];
      if (!applies) why = control.why_not;
    }
    if (!why.empty()) ImGui::BeginDisabled();
    switch (control.kind) {
      case SettingControl::Kind::number:
        if (control.log_scale) {
          log_drag(label.c_str(), &control.value, control.low, control.high,
                   control.format.c_str());
          if (why.empty()) log_drag_tooltip();
        } else {
          ImGui::DragFloat(label.c_str(), &control.value, (control.high - control.low) / 400.0f,
                           control.low, control.high, control.format.c_str(),
                           ImGuiSliderFlags_AlwaysClamp);
        }
        break;
      case SettingControl::Kind::integer:
        ImGui::DragInt(label.c_str(), &control.whole, drag_speed_iterations,
                       static_cast<int>(control.low), static_cast<int>(control.high), "%d",
                       ImGuiSliderFlags_AlwaysClamp);
        break;
      case SettingControl::Kind::toggle:
        ImGui::Checkbox(label.c_str(), &control.on);
        if (why.empty() && !control.help.empty() && ImGui::IsItemHovered())
          ImGui::SetTooltip("%s", control.help.c_str());
        break;
      case SettingControl::Kind::heading:
        ImGui::DragFloat(label.c_str(), &control.value, (control.high - control.low) / 400.0f,
                         control.low, control.high, control.format.c_str(),
                         ImGuiSliderFlags_AlwaysClamp);
        ImGui::DragFloat((control.label + " heading" + suffix).c_str(), &control.heading, 1.0f,
                         0.0f, 360.0f, "%.0f deg", ImGuiSliderFlags_AlwaysClamp);
        break;
      case SettingControl::Kind::choice: {
        const int count = static_cast<int>(control.choices.size());
        if (control.whole < 0 || control.whole >= count) control.whole = 0;
        if (ImGui::BeginCombo(label.c_str(), control.choices[control.whole].c_str())) {
          for (int i = 0; i < count; ++i) {
            if (ImGui::Selectable(control.choices[i].c_str(), i == control.whole))
              control.whole = i;
          }
          ImGui::EndCombo();
        }
        if (why.empty() && !control.help.empty() && ImGui::IsItemHovered())
          ImGui::SetTooltip("%s", control.help.c_str());
        break;
      }
    }
    if (!why.empty()) {
      ImGui::EndDisabled();
      if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s", why.c_str());
    }
  }
}

}  // namespace

SettingControl* SideSliders::control(const std::string& name) {
  for (SettingControl& control : controls) {
    if (control.name == name) return &control;
  }
  return nullptr;
}

const SettingControl* SideSliders::control(const std::string& name) const {
  for (const SettingControl& control : controls) {
    if (control.name == name) return &control;
  }
  return nullptr;
}

bool draw_simulation_section(SimulationSettings& settings, bool course_scene) {
  draw_setting_controls(settings.controls, "", course_scene);
  const bool restore_defaults = ImGui::Button("Restore defaults");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("The scene as it opened: its settings, pins, colliders and start");
  }
  return restore_defaults;
}

void draw_environment_section(EnvironmentSettings& settings, const EnvironmentOffer& offer) {
  draw_setting_controls(settings.environment.controls, "", offer.course_scene);
  if (offer.colliders) ImGui::Checkbox("colliders", &settings.colliders);
}

void draw_view_section(ViewSettings& settings) {
  ImGui::Checkbox("surface", &settings.surface);
  ImGui::SameLine();
  ImGui::Checkbox("wireframe", &settings.wireframe);
  ImGui::SameLine();
  ImGui::Checkbox("ground", &settings.ground);
  ImGui::Checkbox("springs", &settings.springs);
  ImGui::SameLine();
  ImGui::Checkbox("points", &settings.points);
  const char* const color_names[] = {"material", "strain", "speed", "contacts", "volume"};
  ImGui::Combo("colour by", &settings.color_by, color_names, IM_ARRAYSIZE(color_names));
  // Dragged like every other number, 0.01 a pixel: a slider jumped to where the click landed.
  ImGui::DragFloat("UI scale", &settings.ui_scale, 0.01f, ViewSettings::min_ui_scale,
                   ViewSettings::max_ui_scale, "%.2f", ImGuiSliderFlags_AlwaysClamp);
}

bool draw_instruments_section(InstrumentSettings& settings) {
  ImGui::Checkbox("convergence", &settings.show_convergence);
  ImGui::SameLine();
  ImGui::Checkbox("energy", &settings.show_energy);
  ImGui::SameLine();
  const bool csv = ImGui::Button("CSV");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "What the plots show, as files: the convergence plot's step as\n"
        "wobble-SCENE-convergence-0001.csv (as --convergence-csv writes a step)\n"
        "and the energy plot's samples as wobble-SCENE-energy-0001.csv");
  }
  return csv;
}

void draw_split_section(SplitSettings& settings, bool student_side) {
  if (student_side) {
    // wobble --student: the right side is the student's step, with the seed's settings.
    ImGui::TextWrapped(
        "right: the student's fast_mass_springs_step_sparse, coloured by its "
        "distance from Wobble's (left)");
    return;
  }
  ImGui::Checkbox("split view: right side", &settings.split);
  if (!settings.split) return;
  draw_setting_controls(settings.right.controls, " right", false);
}

}  // namespace wobble

#include "control_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "panel_stats.h"

namespace wobble {

namespace {

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

}  // namespace

PanelPlace draw_control_panel(const PanelParts& parts, const PanelStats& stats, const bool& paused,
                              float ui_scale) {
  PanelPlace place;
  const ImGuiStyle& style = ImGui::GetStyle();
  ImGui::SetNextWindowPos(ImVec2(10.0f * ui_scale, 10.0f * ui_scale), ImGuiCond_FirstUseEver);
  // A fixed width, since its widgets take the window's width; as tall as its contents, never
  // taller than the display. Where the display is shorter, the sections scroll in a list of
  // their own and the stats stay pinned under it.
  const float width = 330.0f * ui_scale;
  // On a screen hardly wider than the panel (a phone held upright) it takes at most the upper
  // part, so that the scene shows below it.
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float room = display.x < width + 200.0f * ui_scale ? 0.55f * display.y : display.y;
  const float tallest = std::max(room - 20.0f * ui_scale, 100.0f * ui_scale);
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, tallest));
  // Begin returns false when the panel is collapsed to its title bar, which covers next to
  // nothing: the view is then framed as if there were no panel.
  place.shown = ImGui::Begin("Wobble", nullptr,
                             ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoScrollbar |
                                 ImGuiWindowFlags_NoScrollWithMouse);
  // A panel left at its margin keeps it in screen points when the scale changes (the page's
  // pixel ratio, the browser's zoom, the UI scale): the margin is 10 points, so it moves with
  // the scale. One the user has dragged elsewhere stays where it was put. (ImGui keeps a
  // window's position in whole pixels, rounded down.)
  ImGuiStorage* storage = ImGui::GetStateStorage();
  const ImGuiID scale_key = ImGui::GetID("scale of the margin");
  const float last_scale = storage->GetFloat(scale_key, ui_scale);
  const float last_margin = std::floor(10.0f * last_scale);
  if (last_scale != ui_scale && ImGui::GetWindowPos().x == last_margin &&
      ImGui::GetWindowPos().y == last_margin) {
    ImGui::SetWindowPos(ImVec2(10.0f * ui_scale, 10.0f * ui_scale));
  }
  storage->SetFloat(scale_key, ui_scale);
  const ImVec2 position = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  place.x = position.x;
  place.y = position.y;
  place.width = size.x;
  place.height = size.y;
  if (!place.shown) {
    // A click or a tap on the folded panel's title bar opens it (ImGui's own needs a double-click
    // or its small arrow, which a finger hardly hits); dragging the title moves it as before.
    const ImGuiIO& io = ImGui::GetIO();
    const float slop = io.MouseDragThreshold;
    if (ImGui::IsWindowHovered() && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
        io.MouseDragMaxDistanceSqr[ImGuiMouseButton_Left] <= slop * slop) {
      ImGui::SetWindowCollapsed(false);
    }
    ImGui::End();
    return place;
  }

  // The list is as tall as its contents were last frame, or as what the panel leaves it.
  const float stats_height =
      static_cast<float>(panel_stats_lines(stats)) * ImGui::GetTextLineHeightWithSpacing();
  const float list_room = tallest - ImGui::GetCursorPosY() - style.WindowPadding.y -
                          2.0f * style.ItemSpacing.y - stats_height - 1.0f;
  const ImGuiID list_height_id = ImGui::GetID("##sections height");
  const float contents_height = storage->GetFloat(list_height_id, list_room);
  float list_height = std::min(contents_height, list_room);
  if (contents_height > list_room) {
    // Too tall for the panel: the list ends under a whole row, never through one. Its rows (the
    // headers, sliders, buttons and boxes) all take a frame's height and the spacing under it.
    const float pitch = ImGui::GetFrameHeightWithSpacing();
    list_height =
        std::floor((list_room + style.ItemSpacing.y) / pitch) * pitch - style.ItemSpacing.y;
  }
  list_height = std::max(list_height, 40.0f * ui_scale);
  ImGui::BeginChild("sections", ImVec2(0.0f, list_height));
  // Widgets take what the labels leave.
  ImGui::PushItemWidth(-120.0f * ui_scale);
  for (const std::function<void()>* rows : {&parts.scene_rows, &parts.save_rows, &parts.play_rows})
    if (*rows) (*rows)();
  const std::pair<const char*, const std::function<void()>*> sections[] = {
      {"simulation", &parts.simulation},
      {"environment", &parts.environment},
      {"view", &parts.view},
      {"instruments", &parts.instruments},
      {"compare", &parts.compare}};
  for (const auto& [title, draw] : sections) {
    if (*draw && section(title)) (*draw)();
  }
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
  draw_panel_stats(stats, paused);
  ImGui::EndChild();
  ImGui::End();
  return place;
}

PanelRequests draw_control_panel(PanelSettings& settings, const PanelStats& stats,
                                 const std::vector<std::string>& scene_names, float ui_scale) {
  PanelRequests requests;
  PanelParts parts;
  std::vector<SceneChoice> scenes;
  for (const std::string& name : scene_names)
    scenes.push_back(SceneChoice{name, "", false});
  parts.scene_rows = [&] {
    static_cast<SceneRowRequests&>(requests) = draw_scene_rows(settings, scenes);
  };
  parts.save_rows = [&] {
    static_cast<SaveRowRequests&>(requests) = draw_save_rows(
        settings.recording, settings.record_format, settings.record_whole_window, stats.recording);
  };
  parts.play_rows = [&] {
    static_cast<PlayRequests&>(requests) = draw_play_rows(settings, stats.warning);
  };
  parts.simulation = [&] {
    requests.restore_defaults = draw_simulation_section(settings, stats.course_scene);
  };
  parts.environment = [&] { draw_environment_section(settings, environment_offer(stats)); };
  parts.view = [&] { draw_view_section(settings); };
  parts.instruments = [&] { draw_instruments_section(settings); };
  parts.compare = [&] { draw_split_section(settings, stats.student_side); };
  requests.place = draw_control_panel(parts, stats, settings.paused, ui_scale);
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

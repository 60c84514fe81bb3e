#ifndef WOBBLE_TESTS_UI_PANEL_DRIVER_H
#define WOBBLE_TESTS_UI_PANEL_DRIVER_H

#include <imgui.h>
#include <imgui_internal.h>

#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "../app/headless_imgui.h"
#include "app/viewer/side_settings.h"
#include "ui/control_panel.h"

namespace wobble::testing {

// The control panel alone in a display of `width` by `height` at `scale` (the viewer's UI scale
// times the screen's), driven as a user drives it: the mouse moved, pressed and wheeled a frame
// at a time. Nothing is drawn.
class PanelDriver {
 public:
  // Both sides' controls and the environment's as the viewer fills them
  // (app/viewer/side_settings.h): the cloth's k of 400 N/m, 50 iterations on the left and 5 on
  // the right, the default environment.
  PanelDriver(float width, float height, float scale) : imgui_(width, height), scale_(scale) {
    ImGui::GetIO().FontGlobalScale = scale;
    SimulationParams params;
    params.k = 400.0;
    show_settings(params, settings);
    show_environment(params);
    params.iterations = 5;
    show_settings(params, settings.right);
  }
  // The environment section's controls showing `params`.
  void show_environment(const SimulationParams& params) {
    show_settings(params, settings.environment, false, PanelPart::environment);
  }
  PanelSettings settings;
  PanelStats stats;
  std::vector<std::string> scenes = {"cloth", "jelly"};

  // One frame with the mouse at `mouse`, its left button down or up, the wheel turned by `wheel`
  // notches (negative: down the list).
  void frame(const ImVec2& mouse = ImVec2(-1.0f, -1.0f), bool down = false, float wheel = 0.0f) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = mouse;
    io.MouseDown[0] = down;
    io.MouseWheel = wheel;
    ImGui::NewFrame();
    draw_control_panel(settings, stats, scenes, scale_);
    ImGui::EndFrame();
  }
  // A new scale (a new pixel ratio or UI scale), as the viewer and the page pass it.
  void set_scale(float scale) {
    scale_ = scale;
    ImGui::GetIO().FontGlobalScale = scale;
  }
  // The panel settles its size over its first frames.
  void settle() {
    for (int i = 0; i < 4; ++i)
      frame();
  }
  static ImGuiWindow* panel() { return ImGui::FindWindowByName("Wobble"); }
  // The panel's child window `name` ("sections", "stats"), or null.
  static ImGuiWindow* child(const char* name) {
    const std::string prefix = std::string("Wobble/") + name + "_";
    for (ImGuiWindow* window : ImGui::GetCurrentContext()->Windows) {
      if (std::strncmp(window->Name, prefix.c_str(), prefix.size()) == 0) return window;
    }
    return nullptr;
  }
  // A point on the sections' widget `label`, found by moving the mouse down the list's left
  // edge (or the panel's, without a list) until ImGui says the widget is hovered; nothing when
  // it is not in view.
  std::optional<ImVec2> find(const char* label) {
    ImGuiWindow* list = child("sections");
    if (list == nullptr) list = panel();
    if (list == nullptr) return std::nullopt;
    const ImGuiID id = list->GetIDNoKeepAlive(label);
    const ImVec2 top = list->Pos, size = list->Size;
    for (float y = top.y + 1.0f; y < top.y + size.y; y += 2.0f) {
      const ImVec2 at(top.x + 12.0f * scale_, y);
      frame(at);
      if (ImGui::GetCurrentContext()->HoveredId == id) return at;
    }
    return std::nullopt;
  }
  // The sections' scroll position after turning the wheel over them until it stops moving.
  float scroll_to(bool bottom) {
    ImGuiWindow* list = child("sections");
    if (list == nullptr) return 0.0f;
    const ImVec2 over(list->Pos.x + 0.5f * list->Size.x, list->Pos.y + 0.5f * list->Size.y);
    float last = -1.0f;
    for (int i = 0; i < 100 && list->Scroll.y != last; ++i) {
      last = list->Scroll.y;
      frame(over, false, bottom ? -1.0f : 1.0f);
      frame(over);
    }
    return list->Scroll.y;
  }
  void click(const ImVec2& at) {
    frame(at, true);
    frame(at, false);
  }
  // Presses at `at`, moves right by `pixels` in `steps` frames and lets go. Half a second
  // passes first, so that the press is not the second click of a double click.
  void drag(const ImVec2& at, float pixels, int steps = 6) {
    for (int i = 0; i < 30; ++i)
      frame(at, false);
    frame(at, true);
    for (int i = 1; i <= steps; ++i)
      frame(ImVec2(at.x + pixels * static_cast<float>(i) / static_cast<float>(steps), at.y), true);
    frame(ImVec2(at.x + pixels, at.y), false);
  }

 private:
  HeadlessImGui imgui_;
  float scale_;
};

}  // namespace wobble::testing

#endif

#ifndef WOBBLE_TESTS_APP_VIEWER_PANEL_FIXTURE_H
#define WOBBLE_TESTS_APP_VIEWER_PANEL_FIXTURE_H

// A Viewer and its panel under real ImGui (fonts built on the CPU, nothing drawn), clicked and
// dragged as a user does, for the tests of what the panel hands to the simulation.
#include <imgui.h>
#include <imgui_internal.h>

#include <optional>
#include <string>

#include "app/viewer/viewer.h"
#include "headless_imgui.h"

namespace wobble::testing {

inline const Eigen::Vector2f panel_window(1280.0f, 720.0f);

struct PanelFixture {
  explicit PanelFixture(wobble::Scene scene,
                        const wobble::ViewerSettings& settings = wobble::ViewerSettings())
      : imgui(panel_window.x(), panel_window.y()),
        viewer(std::move(scene), settings, wobble::builtin_scene_names()) {
    viewer.render(1280, 720, panel_window, 1.0f);
    // The panel sizes itself to its contents over its first frames.
    for (int i = 0; i < 3; ++i)
      ui_frame(ImVec2(-1.0f, -1.0f), false);
  }
  // The panel with the mouse at `mouse`, its left button down or up, the wheel turned by `wheel`
  // notches (negative: down the list); no step.
  void ui_frame(const ImVec2& mouse, bool down, float wheel = 0.0f) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = mouse;
    io.MouseDown[0] = down;
    io.MouseWheel = wheel;
    ImGui::NewFrame();
    viewer.build_ui(wobble::PanelStats(), 1.0f);
    ImGui::EndFrame();
  }
  // A point on the panel's widget `label`, found by moving the mouse down the left edge of the
  // panel's list of sections until ImGui says the widget is hovered; nothing when the panel
  // does not draw it.
  std::optional<ImVec2> find(const char* label) {
    ImGuiWindow* panel = nullptr;
    for (ImGuiWindow* window : ImGui::GetCurrentContext()->Windows) {
      if (std::string(window->Name).rfind("Wobble/sections_", 0) == 0) panel = window;
    }
    if (panel == nullptr) return std::nullopt;
    const ImGuiID id = panel->GetIDNoKeepAlive(label);
    const ImVec2 top = panel->Pos, size = panel->Size;
    for (float y = top.y + 1.0f; y < top.y + size.y; y += 2.0f) {
      const ImVec2 at(top.x + 16.0f, y);
      ui_frame(at, false);
      if (ImGui::GetCurrentContext()->HoveredId == id) return at;
    }
    return std::nullopt;
  }
  void click(const ImVec2& at) {
    ui_frame(at, true);
    ui_frame(at, false);
  }
  // find(), scrolling the list down a notch at a time until `label` shows.
  std::optional<ImVec2> scroll_to(const char* label) {
    std::optional<ImVec2> at = find(label);
    for (int notch = 0; !at && notch < 40; ++notch) {
      ui_frame(ImVec2(100.0f, 300.0f), false, -1.0f);
      at = find(label);
    }
    return at;
  }
  // Opens the combo `combo` and clicks its item `item`; false when either is not there.
  bool choose(const char* combo, const char* item) {
    const std::optional<ImVec2> at = scroll_to(combo);
    if (!at) return false;
    click(*at);
    ImGuiWindow* popup = nullptr;
    for (ImGuiWindow* window : ImGui::GetCurrentContext()->Windows) {
      if (std::string(window->Name).rfind("##Combo_", 0) == 0 && window->Active) popup = window;
    }
    if (popup == nullptr) return false;
    const ImGuiID id = popup->GetIDNoKeepAlive(item);
    for (float y = popup->Pos.y + 1.0f; y < popup->Pos.y + popup->Size.y; y += 2.0f) {
      const ImVec2 over(popup->Pos.x + 12.0f, y);
      ui_frame(over, false);
      if (ImGui::GetCurrentContext()->HoveredId == id) {
        click(over);
        return true;
      }
    }
    return false;
  }
  // Drags from `at` by `dx` pixels to the right, in steps, the button held between.
  void drag(const ImVec2& at, float dx) {
    ui_frame(at, true);
    for (int step = 1; step <= 10; ++step)
      ui_frame(ImVec2(at.x + dx * step / 10.0f, at.y), true);
    ui_frame(ImVec2(at.x + dx, at.y), false);
  }
  HeadlessImGui imgui;
  Viewer viewer;
};

}  // namespace wobble::testing

#endif

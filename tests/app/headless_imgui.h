#ifndef WOBBLE_TESTS_APP_HEADLESS_IMGUI_H
#define WOBBLE_TESTS_APP_HEADLESS_IMGUI_H

#include <imgui.h>

namespace wobble::testing {

// An ImGui context with no backend, its fonts built on the CPU: enough for Viewer::build_ui to
// lay the panel out (nothing is drawn). `width` by `height` is the display, in ImGui's units.
class HeadlessImGui {
 public:
  HeadlessImGui(float width, float height) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(width, height);
    unsigned char* pixels = nullptr;
    int texture_width = 0, texture_height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &texture_width, &texture_height);
  }
  ~HeadlessImGui() { ImGui::DestroyContext(); }
  HeadlessImGui(const HeadlessImGui&) = delete;
  HeadlessImGui& operator=(const HeadlessImGui&) = delete;
};

}  // namespace wobble::testing

#endif

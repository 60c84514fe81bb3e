#include "color_legend.h"

#include <imgui.h>

#include <algorithm>

#include "instrument_windows.h"

namespace wobble {

namespace {

ImU32 packed(const std::vector<float>& colors, std::size_t sample) {
  const float* rgb = colors.data() + 3 * sample;
  return ImGui::ColorConvertFloat4ToU32(ImVec4(rgb[0], rgb[1], rgb[2], 1.0f));
}

}  // namespace

void draw_color_legend(const ColorLegend& legend, float ui_scale,
                       const LegendClearance& clearance) {
  const std::size_t samples = legend.colors.size() / 3;
  if (samples < 2) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float margin = 10.0f * ui_scale;
  float right = display.x - margin, bottom = display.y - margin;
  if (clearance.instrument_column_left >= 0.0f)
    right = std::min(right, clearance.instrument_column_left - margin);
  // The labels are two lines, and a third for the right side's warning (side_labels.cpp).
  if (clearance.side_labels) bottom -= 3.0f * ImGui::GetTextLineHeightWithSpacing() + 2.0f * margin;
  ImGui::SetNextWindowPos(ImVec2(right, bottom), ImGuiCond_Always, ImVec2(1.0f, 1.0f));
  ImGui::SetNextWindowBgAlpha(0.75f);
  // Not a control: it never takes the mouse from the 3-D view or the keyboard focus.
  ImGui::Begin("Colour legend", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
  ImGui::TextUnformatted(legend.title.c_str());

  // The bar: one horizontal gradient per pair of neighbouring samples, so it shows the map's
  // own curve rather than a straight blend of its ends.
  const float width = 220.0f * ui_scale, height = 14.0f * ui_scale;
  const ImVec2 corner = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float step = width / static_cast<float>(samples - 1);
  for (std::size_t i = 0; i + 1 < samples; ++i) {
    const ImU32 left = packed(legend.colors, i), right = packed(legend.colors, i + 1);
    const float x = corner.x + step * static_cast<float>(i);
    // The next segment starts where this one ends; rounding to whole pixels leaves no seams.
    draw->AddRectFilledMultiColor(ImVec2(x, corner.y), ImVec2(x + step + 0.5f, corner.y + height),
                                  left, right, right, left);
  }
  draw->AddRect(corner, ImVec2(corner.x + width, corner.y + height),
                ImGui::GetColorU32(ImGuiCol_Border));
  ImGui::Dummy(ImVec2(width, height));

  // Labels under the bar's ends and centre.
  const float row = ImGui::GetCursorPosY();
  const float left_x = ImGui::GetCursorPosX();
  ImGui::TextUnformatted(legend.low.c_str());
  if (!legend.middle.empty()) {
    const float middle_width = ImGui::CalcTextSize(legend.middle.c_str()).x;
    ImGui::SetCursorPos(ImVec2(left_x + 0.5f * (width - middle_width), row));
    ImGui::TextUnformatted(legend.middle.c_str());
  }
  const float high_width = ImGui::CalcTextSize(legend.high.c_str()).x;
  ImGui::SetCursorPos(ImVec2(left_x + std::max(0.0f, width - high_width), row));
  ImGui::TextUnformatted(legend.high.c_str());
  if (!legend.note.empty()) ImGui::TextDisabled("%s", legend.note.c_str());
  ImGui::End();
}

}  // namespace wobble

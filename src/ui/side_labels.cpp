#include "side_labels.h"

#include <imgui.h>

namespace wobble {

namespace {

void corner_text(ImDrawList* draw, ImVec2 at, const std::string& text, ImU32 color, float pad) {
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  draw->AddRectFilled(ImVec2(at.x - pad, at.y - size.y - 2.0f * pad),
                      ImVec2(at.x + size.x + pad, at.y), IM_COL32(15, 16, 20, 200), 3.0f);
  draw->AddText(ImVec2(at.x, at.y - size.y - pad), color, text.c_str());
}

}  // namespace

void draw_side_labels(const SideLabels& labels, float ui_scale) {
  // Under every window (the panel, the plots, the help), over the scene: the divider once ran
  // across the help overlay.
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float left = labels.half > 0.0f ? labels.area_left : 0.0f;
  const float width = labels.half > 0.0f ? labels.half : 0.5f * display.x;
  const float half = left + width, right = left + 2.0f * width;
  draw->AddLine(ImVec2(half, 0.0f), ImVec2(half, display.y), IM_COL32(230, 230, 235, 255),
                2.0f * ui_scale);
  const float margin = 12.0f * ui_scale, pad = 5.0f * ui_scale;
  const ImU32 white = IM_COL32(240, 240, 240, 255);
  // Bottom right of each half, which begin right of the panel and end left of the plots.
  const auto right_aligned = [&](float right_edge, float bottom, const std::string& text,
                                 ImU32 color) {
    const float width = ImGui::CalcTextSize(text.c_str()).x;
    corner_text(draw, ImVec2(right_edge - margin - width, bottom), text, color, pad);
  };
  right_aligned(half, display.y - margin, labels.left, white);
  right_aligned(right, display.y - margin, labels.right, white);
  if (!labels.right_warning.empty()) {
    const float above = ImGui::CalcTextSize(labels.right.c_str()).y + 3.0f * pad;
    right_aligned(right, display.y - margin - above, labels.right_warning,
                  IM_COL32(255, 190, 60, 255));
  }
}

}  // namespace wobble

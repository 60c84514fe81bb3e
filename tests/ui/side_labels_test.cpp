// The split view's divider and corner labels are drawn under every window (the help overlay,
// the panel, the plots), not over them: they go to ImGui's background draw list, which ImGui
// draws before its windows.
#include "ui/side_labels.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include "../app/headless_imgui.h"

TEST(SideLabels, AreDrawnUnderTheWindows) {
  wobble::testing::HeadlessImGui imgui(1280.0f, 720.0f);
  ImGui::NewFrame();
  const int foreground = ImGui::GetForegroundDrawList()->VtxBuffer.Size;
  const int background = ImGui::GetBackgroundDrawList()->VtxBuffer.Size;
  wobble::SideLabels labels;
  labels.left = "50 iterations, plain";
  labels.right = "5 iterations, plain";
  labels.area_left = 340.0f;
  labels.half = 470.0f;
  wobble::draw_side_labels(labels, 1.0f);
  EXPECT_GT(ImGui::GetBackgroundDrawList()->VtxBuffer.Size, background) << "drawn";
  EXPECT_EQ(ImGui::GetForegroundDrawList()->VtxBuffer.Size, foreground) << "nothing over windows";
  ImGui::EndFrame();
}

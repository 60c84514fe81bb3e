// ViewerPanel, the viewer's panel, on its own: its keys, the layers a faceless shape shows, and
// its window drawn under real ImGui (fonts built on the CPU, nothing drawn): shown, hidden by
// Tab, or opening folded on a phone's screen.
#include "app/viewer/viewer_panel.h"

#include <gtest/gtest.h>

#include "../headless_imgui.h"

namespace {

wobble::ViewerPanel make_panel(bool folded = false) {
  return wobble::ViewerPanel(wobble::ViewLayers(), wobble::ColorQuantity::material,
                             wobble::viewer_bindings(), wobble::PageActions(), folded);
}

TEST(ViewerPanelComponent, TakesItsOwnKeysAndLeavesTheOthers) {
  wobble::ViewerPanel panel = make_panel();
  EXPECT_FALSE(panel.paused());
  EXPECT_TRUE(panel.command(wobble::ViewerCommand::toggle_pause));
  EXPECT_TRUE(panel.paused());
  EXPECT_TRUE(panel.command(wobble::ViewerCommand::toggle_wireframe));
  EXPECT_TRUE(panel.layers().wireframe);
  EXPECT_TRUE(panel.command(wobble::ViewerCommand::cycle_color_by));
  EXPECT_NE(panel.color_by(), wobble::ColorQuantity::material);
  EXPECT_TRUE(panel.command(wobble::ViewerCommand::toggle_help));
  EXPECT_TRUE(panel.help_shown());
  EXPECT_TRUE(panel.command(wobble::ViewerCommand::close_overlays));
  EXPECT_FALSE(panel.help_shown());
  EXPECT_TRUE(panel.command(wobble::ViewerCommand::toggle_panel));
  EXPECT_FALSE(panel.shown());
  EXPECT_FALSE(panel.quit_requested());
  EXPECT_TRUE(panel.command(wobble::ViewerCommand::quit));
  EXPECT_TRUE(panel.quit_requested());
  // The simulation's, the camera's and the files' are not the panel's.
  for (const wobble::ViewerCommand other :
       {wobble::ViewerCommand::reset, wobble::ViewerCommand::step_once,
        wobble::ViewerCommand::frame_mesh, wobble::ViewerCommand::save_scene,
        wobble::ViewerCommand::toggle_wind}) {
    EXPECT_FALSE(panel.command(other));
  }
}

TEST(ViewerPanelComponent, AShapeWithoutFacesShowsItsSpringsAndPointsUntilOneWithFaces) {
  wobble::ViewerPanel panel = make_panel();
  panel.show_shape(/*has_faces=*/true);
  EXPECT_FALSE(panel.layers().springs);
  panel.show_shape(/*has_faces=*/false);
  EXPECT_TRUE(panel.faceless());
  EXPECT_TRUE(panel.layers().springs);
  EXPECT_TRUE(panel.layers().points);
  panel.show_shape(/*has_faces=*/true);
  EXPECT_FALSE(panel.layers().springs) << "what was chosen for meshes with faces comes back";
  EXPECT_FALSE(panel.layers().points);
}

wobble::PanelPlace draw_frames(wobble::ViewerPanel& panel, int frames) {
  wobble::PanelPlace place;
  for (int i = 0; i < frames; ++i) {
    ImGui::NewFrame();
    panel.draw(wobble::PanelParts(), wobble::PanelStats(), {}, "", 1.0f);
    ImGui::EndFrame();
    place = panel.place();
  }
  return place;
}

TEST(ViewerPanelComponent, DrawsItsWindowAndHiddenCoversNothing) {
  wobble::testing::HeadlessImGui imgui(1280.0f, 720.0f);
  wobble::ViewerPanel panel = make_panel();
  const wobble::PanelPlace open = draw_frames(panel, 3);
  EXPECT_TRUE(open.shown);
  EXPECT_TRUE(panel.open());
  EXPECT_GT(open.width, 100.0f);
  panel.command(wobble::ViewerCommand::toggle_panel);
  EXPECT_FALSE(draw_frames(panel, 1).shown);
}

TEST(ViewerPanelComponent, OnAPhonesScreenItOpensFoldedToItsTitleBar) {
  wobble::testing::HeadlessImGui phone(360.0f, 720.0f);
  wobble::ViewerPanel folded = make_panel(/*folded=*/true);
  draw_frames(folded, 3);
  EXPECT_FALSE(folded.open()) << "folded to its title bar";
  EXPECT_TRUE(folded.shown());
}

}  // namespace

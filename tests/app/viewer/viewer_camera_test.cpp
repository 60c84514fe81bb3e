// The viewer's camera through its real input path, without GL: framing beside the panel (F),
// room for the motion after a reset, the opening view (O), and the limits on orbit and zoom.
// The panel is real ImGui with its fonts built on the CPU, so nothing is drawn.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <optional>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "../../shared_constants.h"
#include "../headless_imgui.h"
#include "../viewer_screen.h"
#include "app/interaction/picking.h"
#include "app/viewer/viewer.h"
#include "io/load_scene.h"

namespace {

using wobble::InputEvent;

using wobble::testing::window;
// The panel at ui_scale 2, a high-DPI laptop's, is 660 units wide and 20 in: its right edge.
constexpr float ui_scale = 2.0f;
constexpr float panel_right = 680.0f;

// An ImGui context with no backend: enough for build_ui to lay the panel out.
struct HeadlessImGui : wobble::testing::HeadlessImGui {
  HeadlessImGui() : wobble::testing::HeadlessImGui(window.x(), window.y()) {}
};

struct CameraFixture {
  explicit CameraFixture(wobble::Scene scene = wobble::make_builtin_scene("cloth"))
      : viewer(std::move(scene), wobble::ViewerSettings(), wobble::builtin_scene_names()) {}
  // One frame as the window runs it, with the panel when `panel` is set.
  void frame(bool panel = false, bool collapsed = false, float scale = ui_scale) {
    if (panel) {
      ImGui::NewFrame();
      if (collapsed) ImGui::SetNextWindowCollapsed(true);
      viewer.build_ui(wobble::PanelStats(), scale);
      ImGui::EndFrame();
    }
    viewer.advance();
    viewer.render(1280, 720, window, 1.0f);
  }
  void send(const InputEvent& event) { viewer.handle_events({event}, false, false, window); }
  void press_key(int key) {
    InputEvent event;
    event.type = InputEvent::Type::key_press;
    event.code = key;
    send(event);
  }
  void drag(const Eigen::Vector2f& from, const Eigen::Vector2f& by) {
    InputEvent event;
    event.type = InputEvent::Type::cursor_move;
    event.x = from.x();
    event.y = from.y();
    send(event);
    event.type = InputEvent::Type::button_press;
    event.code = GLFW_MOUSE_BUTTON_LEFT;
    send(event);
    event.type = InputEvent::Type::cursor_move;
    event.x += by.x();
    event.y += by.y();
    send(event);
    event.type = InputEvent::Type::button_release;
    send(event);
  }
  void wheel(double steps) {
    InputEvent event;
    event.type = InputEvent::Type::scroll;
    event.y = steps;
    send(event);
  }
  // Where vertex i is drawn, in window coordinates.
  Eigen::Vector2f on_screen(int i) const {
    return wobble::testing::vertex_on_screen(viewer, i, window);
  }
  wobble::Viewer viewer;
};

// Where the panel ends and the convergence plot begins (window units), as ImGui placed them.
struct Columns {
  float panel_right, plots_left, plots_width;
};
std::optional<Columns> panel_and_plots() {
  const ImGuiWindow* plots = ImGui::FindWindowByName("Convergence of the last step");
  const ImGuiWindow* panel = ImGui::FindWindowByName("Wobble");
  if (plots == nullptr || panel == nullptr) return std::nullopt;
  return Columns{panel->Pos.x + panel->Size.x, plots->Pos.x, plots->Size.x};
}

TEST(ViewerCamera, FFramesTheClothBesideThePanel) {
  HeadlessImGui imgui;
  CameraFixture f;
  f.frame();  // framed with no panel: the whole window
  const int left_pin = f.on_screen(f.viewer.session().scene().pins[0]).x() <
                               f.on_screen(f.viewer.session().scene().pins[1]).x()
                           ? f.viewer.session().scene().pins[0]
                           : f.viewer.session().scene().pins[1];
  ASSERT_LT(f.on_screen(left_pin).x(), panel_right) << "the pin starts behind the panel";
  f.frame(/*panel=*/true);
  f.press_key(GLFW_KEY_F);
  f.frame(/*panel=*/true);
  for (const int pin : f.viewer.session().scene().pins) {
    const Eigen::Vector2f at = f.on_screen(pin);
    EXPECT_GT(at.x(), panel_right + 20.0f) << "pin " << pin;
    EXPECT_LT(at.x(), window.x()) << "pin " << pin;
    EXPECT_GT(at.y(), 0.0f) << "pin " << pin;
    EXPECT_LT(at.y(), window.y()) << "pin " << pin;
  }
  // The shape sits in the middle of what the panel leaves free.
  const Eigen::Vector2f middle = 0.5f * (f.on_screen(f.viewer.session().scene().pins[0]) +
                                         f.on_screen(f.viewer.session().scene().pins[1]));
  EXPECT_NEAR(middle.x(), 0.5f * (panel_right + window.x()), 0.1f * window.x());
}

// G opens the plots in a column at the right: the cloth moves into what the panel and the plots
// leave free, both pins in sight (they hid the right pin and half the cloth), and F frames there.
TEST(ViewerCamera, OpeningThePlotsMovesTheClothBetweenThePanelAndThem) {
  // At a UI scale of 1 (at 2 the panel and the plots leave too little between them even with the
  // column narrowed, and the cloth is framed in the whole window behind them).
  HeadlessImGui imgui;
  CameraFixture f;
  const auto frame = [&f] { f.frame(/*panel=*/true, false, 1.0f); };
  frame();
  f.press_key(GLFW_KEY_G);
  for (int i = 0; i < 3; ++i)
    frame();
  const std::optional<Columns> columns = panel_and_plots();
  ASSERT_TRUE(columns);
  const float plots_left = columns->plots_left, panel_right = columns->panel_right;
  ASSERT_GT(plots_left - panel_right, 0.25f * window.x());
  const auto in_between = [&] {
    for (const int pin : f.viewer.session().scene().pins) {
      const Eigen::Vector2f at = f.on_screen(pin);
      EXPECT_GT(at.x(), panel_right) << "pin " << pin;
      EXPECT_LT(at.x(), plots_left) << "pin " << pin;
    }
  };
  in_between();
  f.drag(Eigen::Vector2f(900.0f, 650.0f), Eigen::Vector2f(300.0f, 0.0f));  // turn away
  f.press_key(GLFW_KEY_F);
  frame();
  in_between();
  // Closed again, the cloth takes the room back.
  f.press_key(GLFW_KEY_G);
  for (int i = 0; i < 3; ++i)
    frame();
  const Eigen::Vector2f middle = 0.5f * (f.on_screen(f.viewer.session().scene().pins[0]) +
                                         f.on_screen(f.viewer.session().scene().pins[1]));
  EXPECT_NEAR(middle.x(), 0.5f * (panel_right + window.x()), 0.1f * window.x())
      << "centred beside the panel again";
}

// At a projector's UI scale (1.5 at 1280 × 720) the plots' column narrows to leave the shape a
// third of the view beside the panel: G then F shows the whole cloth and the whole jelly there.
// (The column kept its full width, the gap was too narrow to frame into, and the shape was
// framed in the whole window: the cloth behind the panel and a pin behind the plots.)
TEST(ViewerCamera, AtAProjectorsScaleGThenFShowsTheShapeBetweenPanelAndPlots) {
  for (const std::string name : {"cloth", "jelly"}) {
    HeadlessImGui imgui;
    CameraFixture f(wobble::make_builtin_scene(name));
    const auto frame = [&f] { f.frame(/*panel=*/true, false, 1.5f); };
    frame();
    f.press_key(GLFW_KEY_G);
    for (int i = 0; i < 3; ++i)
      frame();
    f.press_key(GLFW_KEY_F);
    for (int i = 0; i < 2; ++i)
      frame();
    const std::optional<Columns> columns = panel_and_plots();
    ASSERT_TRUE(columns) << name;
    const float plots_left = columns->plots_left, panel_right = columns->panel_right;
    EXPECT_GE(plots_left - panel_right, 0.25f * window.x()) << name;
    EXPECT_GT(columns->plots_width, 0.25f * window.x()) << name << ": the plots still readable";
    const int n = static_cast<int>(f.viewer.session().simulation().positions().rows());
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector2f at = f.on_screen(i);
      ASSERT_GT(at.x(), panel_right) << name << ": vertex " << i << " behind the panel";
      ASSERT_LT(at.x(), plots_left) << name << ": vertex " << i << " behind the plots";
      ASSERT_TRUE(at.y() > 0.0f && at.y() < window.y()) << name << ": vertex " << i;
    }
  }
}

// Tab hides the panel: the shape is framed again in the whole window, and again beside the panel
// when it comes back (it stayed where the panel had left room for it).
TEST(ViewerCamera, TabHidingThePanelFramesAgain) {
  HeadlessImGui imgui;
  CameraFixture f;
  const auto frame = [&f] { f.frame(/*panel=*/true, false, 1.0f); };
  const auto middle_x = [&f] {
    return 0.5f * (f.on_screen(f.viewer.session().scene().pins[0]).x() +
                   f.on_screen(f.viewer.session().scene().pins[1]).x());
  };
  for (int i = 0; i < 2; ++i)
    frame();
  const ImGuiWindow* panel = ImGui::FindWindowByName("Wobble");
  ASSERT_NE(panel, nullptr);
  const float beside = 0.5f * (panel->Pos.x + panel->Size.x + window.x());
  EXPECT_NEAR(middle_x(), beside, 0.1f * window.x());
  f.press_key(GLFW_KEY_TAB);
  for (int i = 0; i < 2; ++i)
    frame();
  EXPECT_NEAR(middle_x(), 0.5f * window.x(), 0.1f * window.x()) << "centred in the window";
  f.press_key(GLFW_KEY_TAB);
  for (int i = 0; i < 2; ++i)
    frame();
  EXPECT_NEAR(middle_x(), beside, 0.1f * window.x()) << "beside the panel again";
}

// A scene with its own camera (the flag) opens in what the panel leaves free: its view, made for
// the whole window, from farther away and shifted there (it opened pressed against the panel
// with two thirds of the view empty).
TEST(ViewerCamera, ASceneCameraOpensBesideThePanel) {
  HeadlessImGui imgui;
  CameraFixture f(wobble::load_scene(std::string(WOBBLE_ASSETS_DIR) + "/flag.json"));
  f.frame(/*panel=*/true);
  f.frame(/*panel=*/true);
  const int n = static_cast<int>(f.viewer.session().simulation().positions().rows());
  float lowest_x = window.x(), highest_x = 0.0f;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2f at = f.on_screen(i);
    lowest_x = std::min(lowest_x, at.x());
    highest_x = std::max(highest_x, at.x());
    ASSERT_TRUE(at.y() >= 0.0f && at.y() <= window.y()) << "vertex " << i;
  }
  EXPECT_GT(lowest_x, panel_right) << "nothing behind the panel";
  EXPECT_LT(highest_x, window.x());
  EXPECT_NEAR(0.5f * (lowest_x + highest_x), 0.5f * (panel_right + window.x()),
              0.15f * (window.x() - panel_right))
      << "in the middle of what is free";
}

TEST(ViewerCamera, ACollapsedPanelCoversNothing) {
  HeadlessImGui imgui;
  CameraFixture f;
  f.frame(/*panel=*/true, /*collapsed=*/true);
  f.press_key(GLFW_KEY_F);
  f.frame(/*panel=*/true, /*collapsed=*/true);
  EXPECT_TRUE(f.viewer.drawing().camera().lens_shift.isZero());
}

TEST(ViewerCamera, TheSplitViewCentresTheShapeInEachHalf) {
  HeadlessImGui imgui;
  CameraFixture f;
  f.frame(/*panel=*/true);
  ASSERT_GT(f.viewer.drawing().camera().lens_shift.x(), 0.1f) << "framed beside the panel";
  f.press_key(GLFW_KEY_2);
  EXPECT_TRUE(f.viewer.drawing().camera().lens_shift.isZero());
  f.press_key(GLFW_KEY_F);
  f.frame(/*panel=*/true);
  EXPECT_TRUE(f.viewer.drawing().camera().lens_shift.isZero()) << "F frames each half whole";
}

TEST(ViewerCamera, FRightAfterResetKeepsTheFallingClothInView) {
  CameraFixture f;
  for (int i = 0; i < 90; ++i)
    f.frame();
  f.press_key(GLFW_KEY_R);  // flat again, about to fall
  f.press_key(GLFW_KEY_F);
  f.frame();
  // Over the fall and the first swings, every vertex stays in the window.
  const int n = static_cast<int>(f.viewer.session().simulation().positions().rows());
  for (int step = 0; step < 120; ++step) {
    f.frame();
    for (int i = 0; i < n; i += 7) {
      const Eigen::Vector2f at = f.on_screen(i);
      ASSERT_TRUE(at.x() >= 0 && at.x() <= window.x() && at.y() >= 0 && at.y() <= window.y())
          << "vertex " << i << " left the view at step " << step << ": " << at.transpose();
    }
  }
}

TEST(ViewerCamera, OGoesBackToTheOpeningView) {
  CameraFixture f;
  f.frame();
  const wobble::OrbitCamera opening = f.viewer.drawing().camera();
  f.drag(Eigen::Vector2f(20, 700), Eigen::Vector2f(200, -150));  // orbit
  f.wheel(3.0);
  ASSERT_GT(std::abs(f.viewer.drawing().camera().yaw - opening.yaw), 0.5f);
  f.press_key(GLFW_KEY_O);
  f.frame();
  EXPECT_NEAR(f.viewer.drawing().camera().yaw, opening.yaw, 1e-6f);
  EXPECT_NEAR(f.viewer.drawing().camera().pitch, opening.pitch, 1e-6f);
  // Framed with room to move around the shape as it is now, which has fallen a little.
  EXPECT_GT(f.viewer.drawing().camera().distance, 0.9f * opening.distance);
  EXPECT_LT(f.viewer.drawing().camera().distance, 1.5f * opening.distance);
}

TEST(ViewerCamera, OGoesBackToASceneOwnCamera) {
  wobble::Scene scene = wobble::make_builtin_scene("cloth");
  scene.look.camera_position = Eigen::Vector3d(0.0, 1.0, 4.0);
  scene.look.camera_target = Eigen::Vector3d(0.0, 1.0, 0.0);
  CameraFixture f(scene);
  f.frame();
  f.drag(Eigen::Vector2f(20, 700), Eigen::Vector2f(200, -150));
  f.press_key(GLFW_KEY_F);
  f.frame();
  f.press_key(GLFW_KEY_O);
  f.frame();
  EXPECT_TRUE(f.viewer.drawing().camera().target.isApprox(Eigen::Vector3f(0, 1, 0)));
  EXPECT_NEAR(f.viewer.drawing().camera().distance, 4.0f, 1e-5f);
  EXPECT_NEAR(f.viewer.drawing().camera().yaw, 0.0f, 1e-6f);
  EXPECT_NEAR(f.viewer.drawing().camera().pitch, 0.0f, 1e-6f);
  EXPECT_TRUE(f.viewer.drawing().camera().lens_shift.isZero());
}

TEST(ViewerCamera, OrbitKeepsTheEyeAboveTheGround) {
  CameraFixture f;
  f.frame();
  // Drag up across the window many times over: the camera would go round under the cloth.
  for (int i = 0; i < 5; ++i)
    f.drag(Eigen::Vector2f(20, 700), Eigen::Vector2f(0, -700));
  EXPECT_GE(wobble::camera_eye(f.viewer.drawing().camera()).y(),
            f.viewer.drawing().ground().height);
  EXPECT_LT(f.viewer.drawing().camera().pitch, 0.2f) << "it does get down near the ground";
}

TEST(ViewerCamera, ZoomStopsOutsideTheShapeAndBeforeItIsADot) {
  CameraFixture f;
  f.frame();
  const Eigen::MatrixXd& V = f.viewer.session().scene().network.V;
  const float radius =
      0.5f * static_cast<float>((V.colwise().maxCoeff() - V.colwise().minCoeff()).norm());
  f.wheel(100.0);
  EXPECT_NEAR(f.viewer.drawing().camera().distance, 0.6f * radius, 1e-4f);
  f.wheel(-200.0);
  EXPECT_NEAR(f.viewer.drawing().camera().distance, 20.0f * radius, 1e-3f);
}

}  // namespace

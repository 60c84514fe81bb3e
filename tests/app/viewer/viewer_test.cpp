// The viewer's input path, in-process and without GL: synthetic mouse and key events go through
// Viewer::handle_events exactly as the window delivers them, and the simulation must respond.
#include "app/viewer/viewer.h"
#include "../viewer_screen.h"

#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <fstream>

#include "../../io/temporary_folder.h"
#include "../../shared_constants.h"
#include "app/interaction/picking.h"
#include "io/load_scene.h"

namespace {

using wobble::InputEvent;

using wobble::testing::window;

struct ViewerFixture {
  explicit ViewerFixture(const wobble::ViewerSettings& settings = wobble::ViewerSettings())
      : viewer(wobble::make_builtin_scene("cloth"), settings, wobble::builtin_scene_names()) {
    // Without a renderer, render() still sets up the camera and the picking arrays.
    viewer.render(1280, 720, window, 1.0f);
  }
  // Where vertex i is drawn, in window coordinates.
  Eigen::Vector2f on_screen(int i) const {
    return wobble::testing::vertex_on_screen(viewer, i, window);
  }
  void send(InputEvent::Type type, const Eigen::Vector2f& at, int code = 0, bool control = false,
            bool ui_wants_mouse = false) {
    InputEvent event;
    event.type = type;
    event.code = code;
    event.control = control;
    event.x = at.x();
    event.y = at.y();
    viewer.handle_events({event}, ui_wants_mouse, false, window);
  }
  void press_key(int key, bool control = false) {
    InputEvent event;
    event.type = InputEvent::Type::key_press;
    event.code = key;
    event.control = control;
    viewer.handle_events({event}, false, false, window);
  }
  void frame() {
    viewer.advance();
    viewer.render(1280, 720, window, 1.0f);
  }
  wobble::Viewer viewer;
};

TEST(Viewer, DraggingAPinnedCornerMovesItAndTheClothFollows) {
  ViewerFixture f;
  const int corner = f.viewer.session().scene().pins[0];
  const Eigen::Vector3d start = f.viewer.session().simulation().positions().row(corner);
  const int factorizations = f.viewer.session().simulation().numeric_factorizations();
  const Eigen::Vector2f at = f.on_screen(corner) + Eigen::Vector2f(3, 2);  // a few pixels off

  f.send(InputEvent::Type::cursor_move, at);
  f.send(InputEvent::Type::button_press, at, GLFW_MOUSE_BUTTON_LEFT);
  // Drag 300 px to the right over 30 frames.
  for (int i = 1; i <= 30; ++i) {
    f.send(InputEvent::Type::cursor_move, at + Eigen::Vector2f(10.0f * i, 0));
    f.frame();
  }
  const Eigen::Vector3d moved = f.viewer.session().simulation().positions().row(corner);
  // The corner went where the cursor went: 300 px to the right on screen ...
  EXPECT_NEAR((f.on_screen(corner) - at).x(), 300.0f - 3.0f, 2.0f);
  EXPECT_NEAR((f.on_screen(corner) - at).y(), -2.0f, 2.0f);
  // ... which is a large move in the world, in the plane facing the camera.
  EXPECT_GT((moved - start).norm(), 0.5);
  EXPECT_NEAR(
      (moved - start).cast<float>().dot(wobble::camera_forward(f.viewer.drawing().camera())), 0.0f,
      1e-3f);
  f.send(InputEvent::Type::button_release, at, GLFW_MOUSE_BUTTON_LEFT);
  EXPECT_TRUE(f.viewer.session().simulation().is_pinned(corner));
  EXPECT_EQ(f.viewer.session().simulation().numeric_factorizations(), factorizations)
      << "moving a pin must not re-factorize";
  // The cloth follows: its centre of mass moved the same way.
  const double centre = f.viewer.session().simulation().positions().col(0).mean();
  EXPECT_GT(centre, f.viewer.session().scene().network.V.col(0).mean() + 0.1);
}

TEST(Viewer, ControlClickTogglesAPin) {
  ViewerFixture f;
  const int vertex = 40 * 20 + 20;  // the middle of the cloth, free
  ASSERT_FALSE(f.viewer.session().simulation().is_pinned(vertex));
  const Eigen::Vector2f at = f.on_screen(vertex);
  f.send(InputEvent::Type::button_press, at, GLFW_MOUSE_BUTTON_LEFT, /*control=*/true);
  f.send(InputEvent::Type::button_release, at, GLFW_MOUSE_BUTTON_LEFT);
  EXPECT_TRUE(f.viewer.session().simulation().is_pinned(vertex));
  EXPECT_EQ(f.viewer.session().simulation().pin_count(), 3);
  f.send(InputEvent::Type::button_press, at, GLFW_MOUSE_BUTTON_LEFT, /*control=*/true);
  f.send(InputEvent::Type::button_release, at, GLFW_MOUSE_BUTTON_LEFT);
  EXPECT_FALSE(f.viewer.session().simulation().is_pinned(vertex));
}

TEST(Viewer, MouseOverThePanelDoesNothingToTheScene) {
  ViewerFixture f;
  const int corner = f.viewer.session().scene().pins[0];
  const Eigen::Vector2f at = f.on_screen(corner);
  const wobble::OrbitCamera before = f.viewer.drawing().camera();
  f.send(InputEvent::Type::button_press, at, GLFW_MOUSE_BUTTON_LEFT, true, /*ui=*/true);
  f.send(InputEvent::Type::cursor_move, at + Eigen::Vector2f(100, 50), 0, false, true);
  f.send(InputEvent::Type::button_release, at, GLFW_MOUSE_BUTTON_LEFT, false, true);
  EXPECT_EQ(f.viewer.session().simulation().pin_count(), 2);
  EXPECT_TRUE(f.viewer.session().simulation().pin_target(corner).isApprox(
      f.viewer.session().scene().network.V.row(corner).transpose()));
  EXPECT_EQ(f.viewer.drawing().camera().yaw, before.yaw);
}

TEST(Viewer, DraggingEmptySpaceOrbitsAndTheWheelZooms) {
  ViewerFixture f;
  const wobble::OrbitCamera before = f.viewer.drawing().camera();
  const Eigen::Vector2f corner_of_window(20, 700);  // nothing drawn there but the ground
  f.send(InputEvent::Type::cursor_move, corner_of_window);
  f.send(InputEvent::Type::button_press, corner_of_window, GLFW_MOUSE_BUTTON_LEFT);
  f.send(InputEvent::Type::cursor_move, corner_of_window + Eigen::Vector2f(72, 0));
  f.send(InputEvent::Type::button_release, corner_of_window, GLFW_MOUSE_BUTTON_LEFT);
  EXPECT_NEAR(f.viewer.drawing().camera().yaw, before.yaw - 72 * 3.14159265f / 720, 1e-4f);
  InputEvent wheel;
  wheel.type = InputEvent::Type::scroll;
  wheel.y = 1.0;
  f.viewer.handle_events({wheel}, false, false, window);
  EXPECT_NEAR(f.viewer.drawing().camera().distance, before.distance / 1.15f, 1e-4f);
}

TEST(Viewer, KeysPauseStepAndReset) {
  ViewerFixture f;
  f.frame();
  EXPECT_EQ(f.viewer.session().simulation().steps_taken(), 1);
  f.press_key(GLFW_KEY_SPACE);  // pause
  f.frame();
  EXPECT_EQ(f.viewer.session().simulation().steps_taken(), 1);
  f.press_key(GLFW_KEY_S);  // one step, still paused
  f.frame();
  f.frame();
  EXPECT_EQ(f.viewer.session().simulation().steps_taken(), 2);
  f.press_key(GLFW_KEY_R);
  EXPECT_EQ(f.viewer.session().simulation().steps_taken(), 0);
  EXPECT_TRUE(
      f.viewer.session().simulation().positions().isApprox(f.viewer.session().scene().network.V));
  f.press_key(GLFW_KEY_SPACE);  // play
  f.frame();
  EXPECT_EQ(f.viewer.session().simulation().steps_taken(), 1);
  EXPECT_FALSE(f.viewer.panel().quit_requested());
  // Esc backs out of things (the help here) and never ends a demo; Ctrl+Q does.
  f.press_key(GLFW_KEY_H);
  EXPECT_TRUE(f.viewer.panel().help_shown());
  f.press_key(GLFW_KEY_ESCAPE);
  EXPECT_FALSE(f.viewer.panel().help_shown());
  EXPECT_FALSE(f.viewer.panel().quit_requested());
  f.press_key(GLFW_KEY_Q);
  EXPECT_FALSE(f.viewer.panel().quit_requested());
  f.press_key(GLFW_KEY_Q, /*control=*/true);
  EXPECT_TRUE(f.viewer.panel().quit_requested());
}

}  // namespace

namespace {

TEST(Viewer, ASceneCameraIsUsedAndTheCommandLineCanTurnIt) {
  wobble::Scene scene = wobble::make_builtin_scene("cloth");
  scene.look.camera_position = Eigen::Vector3d(0.0, 1.0, 4.0);
  scene.look.camera_target = Eigen::Vector3d(0.0, 1.0, 0.0);
  const wobble::Viewer from_scene(scene, wobble::ViewerSettings(), {"cloth"});
  EXPECT_TRUE(from_scene.drawing().camera().target.isApprox(Eigen::Vector3f(0, 1, 0)));
  EXPECT_NEAR(from_scene.drawing().camera().distance, 4.0f, 1e-5f);
  EXPECT_NEAR(from_scene.drawing().camera().yaw, 0.0f, 1e-6f);
  EXPECT_NEAR(from_scene.drawing().camera().pitch, 0.0f, 1e-6f);

  wobble::ViewerSettings turned;
  turned.camera_yaw_degrees = 90.0f;
  const wobble::Viewer overridden(scene, turned, {"cloth"});
  EXPECT_NEAR(overridden.drawing().camera().yaw, 3.14159265f / 2, 1e-5f);
  EXPECT_NEAR(overridden.drawing().camera().distance, 4.0f, 1e-5f);
}

}  // namespace

namespace {

TEST(Viewer, AFailedStepPausesWithAWarningAndResetClearsIt) {
  wobble::ViewerSettings settings;
  // At frame 2, fling a corner 100 km: far beyond the cloth's jump limit.
  settings.drags = {wobble::parse_drag("0:1e5,0,0@2-2", 100)};
  wobble::Viewer viewer(wobble::make_builtin_scene("cloth"), settings,
                        wobble::builtin_scene_names());
  viewer.advance();
  ASSERT_EQ(viewer.session().simulation().steps_taken(), 1);
  EXPECT_EQ(viewer.session().step_warning(), "");
  const Eigen::MatrixXd after_one = viewer.session().simulation().positions();

  viewer.advance();
  EXPECT_EQ(viewer.session().simulation().last_step_status(), wobble::StepStatus::jumped);
  EXPECT_EQ(viewer.session().simulation().steps_taken(), 1);
  EXPECT_EQ(viewer.session().simulation().positions(), after_one) << "rolled back";
  EXPECT_NE(viewer.session().step_warning().find("Paused at step 2"), std::string::npos)
      << viewer.session().step_warning();
  // The corner was flung by a drag: the advice says so, not "a smaller dt".
  EXPECT_NE(viewer.session().step_warning().find("drag more slowly"), std::string::npos)
      << viewer.session().step_warning();
  EXPECT_EQ(viewer.session().stats().warning, viewer.session().step_warning());
  viewer.advance();
  EXPECT_EQ(viewer.session().simulation().steps_taken(), 1) << "paused";

  InputEvent reset;
  reset.type = InputEvent::Type::key_press;
  reset.code = GLFW_KEY_R;
  viewer.handle_events({reset}, false, false, window);
  EXPECT_EQ(viewer.session().step_warning(), "");
  EXPECT_EQ(viewer.session().simulation().steps_taken(), 0);
}

}  // namespace

namespace {

// Springs without faces as each loader makes them: a course scene of two-vertex faces, a bare
// OBJ of `l` lines, and a Wobble scene whose OBJ has no triangles. Returns their paths.
std::vector<std::string> faceless_scene_files(const wobble::testing::TemporaryFolder& folder) {
  const std::string chain = "v 0 1 0\nv 0.2 1 0\nv 0.4 1 0\nv 0.6 1 0\n";
  std::ofstream(folder.file("chain.obj")) << chain << "f 1 2\nf 2 3\nf 3 4\n";
  std::ofstream(folder.file("course.json")) << R"({"obj": "chain.obj", "b": [1], "k": 50, "m": 1})";
  std::ofstream(folder.file("lines.obj")) << chain << "l 1 2 3 4\n";
  std::ofstream(folder.file("wobble.json")) << R"({"mesh": {"file": "lines.obj"}, "pins": 0})";
  return {folder.file("course.json"), folder.file("lines.obj"), folder.file("wobble.json")};
}

using wobble::testing::press;

TEST(Viewer, AMeshWithoutFacesShowsItsSpringsAndVertices) {
  wobble::testing::TemporaryFolder folder;
  for (const std::string& file : faceless_scene_files(folder)) {
    SCOPED_TRACE(file);
    const wobble::Viewer viewer(wobble::load_scene(file), wobble::ViewerSettings(), {});
    ASSERT_EQ(viewer.session().scene().network.F.rows(), 0);
    ASSERT_GT(viewer.session().scene().network.E.rows(), 0);
    EXPECT_TRUE(viewer.panel().layers().springs);
    EXPECT_TRUE(viewer.panel().layers().points);
  }
  // A mesh with faces keeps the plain defaults: surface only.
  const wobble::Viewer cloth(wobble::make_builtin_scene("cloth"), wobble::ViewerSettings(), {});
  EXPECT_FALSE(cloth.panel().layers().springs);
  EXPECT_FALSE(cloth.panel().layers().points);
  EXPECT_TRUE(cloth.panel().layers().surface);
}

TEST(Viewer, TheUserCanHideThemAndAMeshWithFacesGetsItsOwnLayersBack) {
  wobble::testing::TemporaryFolder folder;
  const std::string chain = faceless_scene_files(folder)[0];
  wobble::ViewerSettings settings;
  settings.layers.points = true;  // as --points asks
  wobble::Viewer viewer(wobble::load_scene(chain), settings, {});
  ASSERT_TRUE(viewer.panel().layers().springs);
  press(viewer, GLFW_KEY_L);
  press(viewer, GLFW_KEY_P);
  EXPECT_FALSE(viewer.panel().layers().springs);
  EXPECT_FALSE(viewer.panel().layers().points);

  // The cloth gets what the command line chose, not what was toggled for the chain ...
  viewer.load(wobble::make_builtin_scene("cloth"));
  EXPECT_FALSE(viewer.panel().layers().springs);
  EXPECT_TRUE(viewer.panel().layers().points);
  // ... a chain again shows both ...
  press(viewer, GLFW_KEY_L);  // springs on, for meshes with faces
  viewer.load(wobble::load_scene(chain));
  EXPECT_TRUE(viewer.panel().layers().springs);
  EXPECT_TRUE(viewer.panel().layers().points);
  // ... and the next mesh with faces has what was chosen for the cloth.
  viewer.load(wobble::make_builtin_scene("jelly"));
  EXPECT_TRUE(viewer.panel().layers().springs);
  EXPECT_TRUE(viewer.panel().layers().points);
  press(viewer, GLFW_KEY_P);
  viewer.load(wobble::make_builtin_scene("cloth"));
  EXPECT_TRUE(viewer.panel().layers().springs);
  EXPECT_FALSE(viewer.panel().layers().points);
}

}  // namespace

namespace {

TEST(Viewer, VCyclesTheColouringAndMaterialComputesNoColours) {
  ViewerFixture fixture;
  wobble::Viewer& viewer = fixture.viewer;
  const std::size_t vertices = viewer.session().scene().network.V.rows();
  const std::size_t springs = viewer.session().scene().network.E.rows();
  fixture.frame();
  EXPECT_EQ(viewer.panel().color_by(), wobble::ColorQuantity::material);
  EXPECT_TRUE(viewer.drawing().quantity_colors().vertex_colors().empty());

  fixture.press_key(GLFW_KEY_V);
  EXPECT_EQ(viewer.panel().color_by(), wobble::ColorQuantity::strain);
  fixture.frame();
  EXPECT_EQ(viewer.drawing().quantity_colors().vertex_colors().size(), 3 * vertices);
  // The springs are not drawn, so they get no colours.
  EXPECT_TRUE(viewer.drawing().quantity_colors().spring_colors().empty());
  fixture.press_key(GLFW_KEY_L);
  fixture.frame();
  EXPECT_EQ(viewer.drawing().quantity_colors().spring_colors().size(), 3 * springs);

  fixture.press_key(GLFW_KEY_V);
  EXPECT_EQ(viewer.panel().color_by(), wobble::ColorQuantity::speed);
  fixture.frame();
  EXPECT_EQ(viewer.drawing().quantity_colors().quantity(), wobble::ColorQuantity::speed);
  EXPECT_GT(viewer.drawing().quantity_colors().range(), wobble::QuantityColors::speed_floor)
      << "the cloth is falling";

  fixture.press_key(GLFW_KEY_V);
  EXPECT_EQ(viewer.panel().color_by(), wobble::ColorQuantity::contacts);
  fixture.frame();
  EXPECT_EQ(viewer.drawing().quantity_colors().quantity(), wobble::ColorQuantity::contacts);
  EXPECT_EQ(viewer.drawing().quantity_colors().vertex_colors().size(), 3 * vertices);
  EXPECT_EQ(viewer.drawing().quantity_colors().range(), 0.0f);

  // The cloth has no tetrahedra: coloured by volume it is neutral, at the range's floor.
  fixture.press_key(GLFW_KEY_V);
  EXPECT_EQ(viewer.panel().color_by(), wobble::ColorQuantity::volume);
  fixture.frame();
  EXPECT_EQ(viewer.drawing().quantity_colors().vertex_colors().size(), 3 * vertices);
  EXPECT_EQ(viewer.drawing().quantity_colors().range(), wobble::QuantityColors::volume_floor);

  fixture.press_key(GLFW_KEY_V);
  EXPECT_EQ(viewer.panel().color_by(), wobble::ColorQuantity::material);
  fixture.frame();
  EXPECT_TRUE(viewer.drawing().quantity_colors().vertex_colors().empty());
  EXPECT_TRUE(viewer.drawing().quantity_colors().spring_colors().empty());
}

TEST(Viewer, StartsColouredAsAskedAndColoursAPausedShape) {
  wobble::ViewerSettings settings;
  settings.color_by = wobble::ColorQuantity::strain;
  wobble::Viewer viewer(wobble::make_builtin_scene("cloth"), settings,
                        wobble::builtin_scene_names());
  InputEvent space;
  space.type = InputEvent::Type::key_press;
  space.code = GLFW_KEY_SPACE;
  viewer.handle_events({space}, false, false, window);
  viewer.advance();
  EXPECT_EQ(viewer.session().simulation().steps_taken(), 0);
  EXPECT_EQ(viewer.drawing().quantity_colors().quantity(), wobble::ColorQuantity::strain);
  EXPECT_EQ(viewer.drawing().quantity_colors().vertex_colors().size(),
            3u * viewer.session().scene().network.V.rows());
}

}  // namespace

// The split view (issue 15): two sides from the same state, each with its own settings.
namespace {

std::unique_ptr<wobble::Viewer> split_viewer(const std::string& compare) {
  wobble::ViewerSettings settings;
  settings.compare = wobble::parse_compare_settings(compare);
  auto viewer = std::make_unique<wobble::Viewer>(wobble::make_builtin_scene("cloth"), settings,
                                                 wobble::builtin_scene_names());
  viewer->render(1280, 720, window, 1.0f);
  return viewer;
}

double largest_difference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

}  // namespace

TEST(SplitView, SameSettingsOnBothSidesStepAlikeToTheBit) {
  const auto owner = split_viewer("iterations=50");
  wobble::Viewer& viewer = *owner;
  ASSERT_NE(viewer.session().right_side(), nullptr);
  for (int frame = 0; frame < 20; ++frame)
    viewer.advance();
  EXPECT_EQ(viewer.session().right_side()->steps_taken(), 20);
  EXPECT_EQ(largest_difference(viewer.session().simulation().positions(),
                               viewer.session().right_side()->positions()),
            0.0);
}

TEST(SplitView, FewerIterationsOnTheRightFallDifferently) {
  const auto owner = split_viewer("iterations=5");
  wobble::Viewer& viewer = *owner;
  EXPECT_EQ(viewer.session().simulation().params().iterations, 50);
  EXPECT_EQ(viewer.session().right_side()->params().iterations, 5);
  for (int frame = 0; frame < 30; ++frame)
    viewer.advance();
  EXPECT_GT(largest_difference(viewer.session().simulation().positions(),
                               viewer.session().right_side()->positions()),
            0.05);
}

TEST(SplitView, HalfTheTimeStepStepsTwiceAFrameAndKeepsTheSameClock) {
  const wobble::Scene scene = wobble::make_builtin_scene("cloth");
  char half_dt[32];
  std::snprintf(half_dt, sizeof(half_dt), "dt=%.17g", scene.params.dt / 2);
  const auto owner = split_viewer(half_dt);
  wobble::Viewer& viewer = *owner;
  for (int frame = 0; frame < 12; ++frame)
    viewer.advance();
  EXPECT_EQ(viewer.session().right_side()->steps_taken(), 24);
  EXPECT_NEAR(viewer.session().right_side()->time(), viewer.session().simulation().time(), 1e-12);
}

TEST(SplitView, ADragActsOnBothSides) {
  const auto owner = split_viewer("iterations=5");
  wobble::Viewer& viewer = *owner;
  const std::vector<int> pins = viewer.session().simulation().pinned_vertices();
  ASSERT_FALSE(pins.empty());
  const int pin = pins.front();
  // Where the pin is drawn in the right half: the same place as in the left, half a window on.
  const Eigen::Vector2f half(640.0f, 720.0f);
  const Eigen::Matrix4f view_projection =
      wobble::projection_matrix(viewer.drawing().camera(), half.x() / half.y()) *
      wobble::view_matrix(viewer.drawing().camera());
  const Eigen::Vector3f p = viewer.session().simulation().positions().row(pin).cast<float>();
  const Eigen::Vector2f at =
      wobble::project_to_window(view_projection, p, half)->head<2>() + Eigen::Vector2f(640, 0);
  const auto send = [&](InputEvent::Type type, const Eigen::Vector2f& where) {
    InputEvent event;
    event.type = type;
    event.code = GLFW_MOUSE_BUTTON_LEFT;
    event.x = where.x();
    event.y = where.y();
    viewer.handle_events({event}, false, false, window);
  };
  const Eigen::Vector3d before = viewer.session().simulation().pin_target(pin);
  send(InputEvent::Type::cursor_move, at);
  send(InputEvent::Type::button_press, at);
  for (int step = 1; step <= 10; ++step) {
    send(InputEvent::Type::cursor_move, at + Eigen::Vector2f(0.0f, 10.0f * step));
    viewer.advance();
    viewer.render(1280, 720, window, 1.0f);
  }
  send(InputEvent::Type::button_release, at + Eigen::Vector2f(0.0f, 100.0f));
  const Eigen::Vector3d after = viewer.session().simulation().pin_target(pin);
  EXPECT_LT(after.y(), before.y() - 0.05) << "dragged down in the right half";
  EXPECT_EQ((viewer.session().right_side()->pin_target(pin) - after).norm(), 0.0);
  // The right side's pinned corner is where the left side's is: both were pulled.
  EXPECT_LT((viewer.session().right_side()->positions().row(pin).transpose() - after).norm(), 1e-6);
}

TEST(SplitView, KeyTwoTogglesItAndResetStartsBothSidesAgain) {
  ViewerFixture fixture;
  EXPECT_EQ(fixture.viewer.session().right_side(), nullptr);
  fixture.press_key(GLFW_KEY_2);
  ASSERT_NE(fixture.viewer.session().right_side(), nullptr);
  EXPECT_EQ(fixture.viewer.session().right_side()->params().iterations, 5);  // a tenth of 50
  for (int frame = 0; frame < 5; ++frame)
    fixture.frame();
  fixture.press_key(GLFW_KEY_R);
  EXPECT_EQ(fixture.viewer.session().right_side()->steps_taken(), 0);
  EXPECT_EQ(largest_difference(fixture.viewer.session().right_side()->positions(),
                               fixture.viewer.session().simulation().positions()),
            0.0);
  fixture.press_key(GLFW_KEY_2);
  EXPECT_EQ(fixture.viewer.session().right_side(), nullptr);
}

TEST(SplitView, EachSideIsColouredByItsOwnShapeInOneRange) {
  const auto owner = split_viewer("iterations=5");
  wobble::Viewer& viewer = *owner;
  InputEvent v;
  v.type = InputEvent::Type::key_press;
  v.code = GLFW_KEY_V;
  viewer.handle_events({v}, false, false, window);
  for (int frame = 0; frame < 20; ++frame)
    viewer.advance();
  // The left side's colours are its own: they differ from what the right side's shape gives.
  const wobble::QuantityColors& left = viewer.drawing().quantity_colors();
  wobble::QuantityColors right;
  right.measure(wobble::ColorQuantity::strain, *viewer.session().right_side());
  right.paint(*viewer.session().right_side(), left.range(), false);
  EXPECT_EQ(left.vertex_colors().size(), right.vertex_colors().size());
  EXPECT_NE(left.vertex_colors(), right.vertex_colors());
  // One range for both: five iterations leave the right side stretchier, so the left side is
  // painted in the right side's range, wider than its own.
  EXPECT_GT(left.range(), 1.5f * left.measured_range());
}

// Issue 16: what a class hits in a demo.
TEST(Viewer, RestoreDefaultsBringsBackTheSceneAsItOpened) {
  ViewerFixture f;
  const wobble::SimulationParams opened = f.viewer.session().simulation().params();
  // Change k, the iterations and the pins as the panel's sliders and a Ctrl+click would (the
  // panel needs an ImGui frame, so the test reaches the simulation directly).
  wobble::Simulation& simulation = const_cast<wobble::Simulation&>(f.viewer.session().simulation());
  simulation.apply(wobble::with_setting(simulation.params(), "k", 5000.0));
  simulation.apply(wobble::with_setting(simulation.params(), "iterations", 7.0));
  simulation.unpin(simulation.pinned_vertices().front());
  for (int frame = 0; frame < 5; ++frame)
    f.frame();
  // What "Restore defaults" loads: the scene as it opened, which the session keeps.
  f.viewer.load(wobble::Scene(f.viewer.session().scene()));
  EXPECT_EQ(f.viewer.session().simulation().params().k, opened.k);
  EXPECT_EQ(f.viewer.session().simulation().params().iterations, opened.iterations);
  EXPECT_EQ(f.viewer.session().simulation().pin_count(), 2);
  EXPECT_EQ(f.viewer.session().simulation().steps_taken(), 0);
}

TEST(Viewer, AFreeVertexHeldByTheMouseIsNotCountedAsAPin) {
  ViewerFixture f;
  const int corner = 40 * 39;  // a bottom corner of the 40×40 cloth, free
  ASSERT_FALSE(f.viewer.session().simulation().is_pinned(corner));
  const Eigen::Vector2f at = f.on_screen(corner);
  f.send(InputEvent::Type::cursor_move, at);
  f.send(InputEvent::Type::button_press, at, GLFW_MOUSE_BUTTON_LEFT);
  ASSERT_EQ(f.viewer.session().simulation().pin_count(), 3) << "held: pinned for the drag";
  EXPECT_EQ(f.viewer.session().stats().pins, 2);
  f.send(InputEvent::Type::button_release, at, GLFW_MOUSE_BUTTON_LEFT);
  EXPECT_EQ(f.viewer.session().stats().pins, 2);
}

TEST(Viewer, PausedAndUntouchedItNeedsNoFrames) {
  ViewerFixture f;
  EXPECT_TRUE(f.viewer.animating()) << "playing";
  f.press_key(GLFW_KEY_SPACE);
  EXPECT_FALSE(f.viewer.animating()) << "paused: the window may wait for input";
  f.press_key(GLFW_KEY_S);
  EXPECT_TRUE(f.viewer.animating()) << "a step asked for";
  f.frame();
  EXPECT_FALSE(f.viewer.animating());
  // Turning the camera (a press on empty space) needs frames until the button is let go.
  const Eigen::Vector2f empty(1200.0f, 60.0f);
  f.send(InputEvent::Type::cursor_move, empty);
  f.send(InputEvent::Type::button_press, empty, GLFW_MOUSE_BUTTON_LEFT);
  EXPECT_TRUE(f.viewer.animating());
  f.send(InputEvent::Type::button_release, empty, GLFW_MOUSE_BUTTON_LEFT);
  EXPECT_FALSE(f.viewer.animating());
}

TEST(Viewer, AFileDroppedOrTypedOpensAndABadOneLeavesTheSceneRunning) {
  ViewerFixture f;
  EXPECT_TRUE(f.viewer.files().open_file(std::string(WOBBLE_ASSETS_DIR) + "/course/rope.json"));
  EXPECT_EQ(f.viewer.session().scene().name, "rope");
  const std::size_t notes = f.viewer.session().scene().notes.size();
  EXPECT_FALSE(f.viewer.files().open_file("/nonexistent/scene.json"));
  EXPECT_EQ(f.viewer.session().scene().name, "rope") << "the current scene keeps running";
  ASSERT_EQ(f.viewer.session().scene().notes.size(), notes + 1);
  EXPECT_NE(f.viewer.session().scene().notes.back().find("/nonexistent/scene.json"),
            std::string::npos)
      << f.viewer.session().scene().notes.back();
}

// The page puts dropped files in a folder of its own; what went wrong names them as the user
// knows them ("banner.json", "'banner.obj'"), not by that folder. A window's keep their paths.
TEST(Viewer, ADroppedFilesReasonNamesItWithoutThePagesFolder) {
  wobble::testing::TemporaryFolder folder;
  const std::string dropped = folder.file("opened_2_a_b_c");
  std::filesystem::create_directories(dropped);
  // The course's banner without its mesh beside it.
  std::filesystem::copy_file(std::string(WOBBLE_ASSETS_DIR) + "/course/banner.json",
                             dropped + "/banner.json");
  for (const bool page : {true, false}) {
    wobble::ViewerSettings settings;
    if (page) settings.page = wobble::PageActions{[] {}, [] {}};
    ViewerFixture f(settings);
    EXPECT_FALSE(f.viewer.files().open_files({dropped + "/banner.json"}));
    const std::string& told = f.viewer.session().scene().notes.back();
    if (page) {
      EXPECT_EQ(told.find(dropped), std::string::npos) << told;
      EXPECT_EQ(told.rfind("banner.json", 0), 0u) << told;
      EXPECT_NE(told.find("'banner.obj'"), std::string::npos) << told;
    } else {
      EXPECT_NE(told.find(dropped + "/banner.json"), std::string::npos) << told;
    }
  }
}

TEST(Viewer, F11ExportsTheCurrentPositionsWithoutReplacingAnEarlierExport) {
  wobble::testing::TemporaryFolder folder;
  const std::filesystem::path before = std::filesystem::current_path();
  std::filesystem::current_path(folder.path());
  {
    ViewerFixture f;
    f.frame();
    f.press_key(GLFW_KEY_F11);
    f.press_key(GLFW_KEY_F11);
    EXPECT_TRUE(std::filesystem::exists("wobble-cloth-0001.obj"));
    EXPECT_TRUE(std::filesystem::exists("wobble-cloth-0002.obj"));
    EXPECT_NE(f.viewer.session().scene().notes.back().find("exported ./wobble-cloth-0002.obj"),
              std::string::npos)
        << f.viewer.session().scene().notes.back();
    // The file holds the positions after the step, not the rest shape.
    std::ifstream obj("wobble-cloth-0001.obj");
    std::string line;
    std::getline(obj, line);  // the header comment
    double x = 0, y = 0, z = 0;
    char v = 0;
    obj >> v >> x >> y >> z;
    EXPECT_EQ(v, 'v');
    EXPECT_DOUBLE_EQ(y, f.viewer.session().simulation().positions()(0, 1));
  }
  std::filesystem::current_path(before);
}

TEST(Viewer, CtrlSSavesTheSceneWithItsPinsAndSettingsAndItOpensSo) {
  wobble::testing::TemporaryFolder folder;
  const std::filesystem::path before = std::filesystem::current_path();
  std::filesystem::current_path(folder.path());
  {
    ViewerFixture f;
    const int vertex = 40 * 20 + 20;  // the middle of the cloth, free
    const Eigen::Vector2f at = f.on_screen(vertex);
    f.send(InputEvent::Type::button_press, at, GLFW_MOUSE_BUTTON_LEFT, /*control=*/true);
    f.send(InputEvent::Type::button_release, at, GLFW_MOUSE_BUTTON_LEFT);
    f.press_key(GLFW_KEY_W);  // the wind on
    f.frame();
    f.press_key(GLFW_KEY_S, /*control=*/true);
    f.press_key(GLFW_KEY_S, /*control=*/true);
    ASSERT_TRUE(std::filesystem::exists("wobble-cloth-scene-0001.json"))
        << f.viewer.session().scene().notes.back();
    EXPECT_TRUE(std::filesystem::exists("wobble-cloth-scene-0001.obj"));
    EXPECT_TRUE(std::filesystem::exists("wobble-cloth-scene-0002.json"));
    EXPECT_NE(f.viewer.session().scene().notes.back().find(
                  "saved the scene as ./wobble-cloth-scene-0002"),
              std::string::npos)
        << f.viewer.session().scene().notes.back();
    // It says so on screen for a while, and the picker offers it under its own name.
    const std::vector<std::string> shown = f.viewer.files().notices().shown(wobble::notice_clock());
    ASSERT_EQ(shown.size(), 2u);
    EXPECT_NE(shown.back().find("wobble-cloth-scene-0002.json"), std::string::npos) << shown.back();
    EXPECT_TRUE(f.viewer.files().notices().shown(wobble::notice_clock() + 60.0).empty());
    const std::vector<std::string>& labels = f.viewer.session().scene_labels();
    EXPECT_NE(std::find(labels.begin(), labels.end(), "wobble-cloth-scene-0001"), labels.end());
    const wobble::Scene saved = wobble::load_scene("wobble-cloth-scene-0001.json");
    EXPECT_EQ(saved.name, "wobble-cloth-scene-0001");
    std::vector<int> pins = saved.pins;
    std::sort(pins.begin(), pins.end());
    EXPECT_EQ(pins, f.viewer.session().simulation().pinned_vertices());
    EXPECT_TRUE(std::find(pins.begin(), pins.end(), vertex) != pins.end());
    EXPECT_TRUE(saved.params.wind.on);
    EXPECT_EQ(saved.params.k, f.viewer.session().simulation().params().k);
    // It opens at the camera the window had.
    ASSERT_TRUE(saved.look.camera_position.has_value());
    EXPECT_LT((saved.look.camera_position->cast<float>() -
               wobble::camera_eye(f.viewer.drawing().camera()))
                  .norm(),
              1e-4f);
  }
  std::filesystem::current_path(before);
}

TEST(Viewer, TabHidesThePanel) {
  ViewerFixture f;
  EXPECT_TRUE(f.viewer.panel().shown());
  f.press_key(GLFW_KEY_TAB);
  EXPECT_FALSE(f.viewer.panel().shown());
  f.press_key(GLFW_KEY_TAB);
  EXPECT_TRUE(f.viewer.panel().shown());
}

TEST(Viewer, APinDraggedWhilePausedIsDrawnAtItsTargetAndStepMovesIt) {
  ViewerFixture f;
  f.press_key(GLFW_KEY_SPACE);  // pause
  const int pin = f.viewer.session().simulation().pinned_vertices().front();
  const Eigen::Vector3d before = f.viewer.session().simulation().positions().row(pin).transpose();
  const Eigen::Vector2f at = f.on_screen(pin);
  f.send(InputEvent::Type::cursor_move, at);
  f.send(InputEvent::Type::button_press, at, GLFW_MOUSE_BUTTON_LEFT);
  f.send(InputEvent::Type::cursor_move, at + Eigen::Vector2f(0.0f, 80.0f));
  f.viewer.render(1280, 720, window, 1.0f);
  const Eigen::Vector3d target = f.viewer.session().simulation().pin_target(pin);
  ASSERT_GT((target - before).norm(), 0.05) << "the drag moved the target";
  EXPECT_EQ(f.viewer.session().simulation().positions().row(pin).transpose(), before) << "paused";
  const std::vector<float>& drawn = f.viewer.drawing().drawn_positions();
  EXPECT_NEAR(drawn[3 * pin + 1], target.y(), 1e-6) << "drawn at the target while paused";
  f.press_key(GLFW_KEY_S);
  f.frame();
  EXPECT_LT((f.viewer.session().simulation().positions().row(pin).transpose() - target).norm(),
            1e-6)
      << "one step takes the pin to its target";
  f.send(InputEvent::Type::button_release, at, GLFW_MOUSE_BUTTON_LEFT);
}

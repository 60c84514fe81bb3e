// The window's way of stepping: batches of steps on a thread of their own (Viewer::exchange)
// while the UI takes input. The results must be the headless ones to the bit, and what the user
// does while a batch runs must reach the simulation after it, in the order it was done.
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <chrono>
#include <memory>
#include <thread>

#include "../shared_constants.h"
#include "app/viewer/viewer.h"
#include "viewer_screen.h"

namespace {

using wobble::InputEvent;

using wobble::testing::window;
constexpr double frame_seconds = 1.0 / 60.0;

wobble::ViewerSettings with_a_scripted_drag() {
  wobble::ViewerSettings settings;
  wobble::ScriptedDrag drag;
  drag.vertex = 40 * 39 + 20;  // the bottom middle of the 40×40 cloth, free
  drag.offset = Eigen::Vector3d(0.3, 0.2, 0.4);
  drag.first_frame = 5;
  drag.last_frame = 25;
  settings.drags.push_back(drag);
  settings.settings.values["dt"] = frame_seconds / 4.0;
  return settings;
}

std::unique_ptr<wobble::Viewer> cloth(
    const wobble::ViewerSettings& settings = wobble::ViewerSettings()) {
  auto viewer = std::make_unique<wobble::Viewer>(wobble::make_builtin_scene("cloth"), settings,
                                                 wobble::builtin_scene_names());
  viewer->render(1280, 720, window, 1.0f);  // the camera, for picking
  return viewer;
}

Eigen::Vector2f on_screen(const wobble::Viewer& viewer, int i) {
  return wobble::testing::vertex_on_screen(viewer, i, window);
}

void control_click(wobble::Viewer& viewer, const Eigen::Vector2f& at) {
  InputEvent press;
  press.type = InputEvent::Type::button_press;
  press.code = GLFW_MOUSE_BUTTON_LEFT;
  press.control = true;
  press.x = at.x();
  press.y = at.y();
  InputEvent release = press;
  release.type = InputEvent::Type::button_release;
  release.control = false;
  viewer.handle_events({press, release}, false, false, window);
}

void press_key(wobble::Viewer& viewer, int key) {
  InputEvent event;
  event.type = InputEvent::Type::key_press;
  event.code = key;
  viewer.handle_events({event}, false, false, window);
}

TEST(ViewerThread, StepsOnTheirThreadGiveTheHeadlessPositionsToTheBit) {
  // Real time, with a dt of a quarter frame: batches of several steps, a scripted drag across
  // them, the frames' clock made up.
  const auto threaded_viewer = cloth(with_a_scripted_drag());
  wobble::Viewer& threaded = *threaded_viewer;
  threaded.session().step_on_thread({});
  double now = 0.0;
  for (int frame = 0; threaded.session().shown_steps() < 40; ++frame) {
    threaded.exchange(now, frame_seconds);
    now += frame_seconds;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    ASSERT_LT(frame, 60000) << "the steps never came";
  }
  threaded.finish_steps();
  const long steps = threaded.session().simulation().steps_taken();
  ASSERT_GE(steps, 40);

  const auto headless_viewer = cloth(with_a_scripted_drag());
  wobble::Viewer& headless = *headless_viewer;
  for (long i = 0; i < steps; ++i)
    headless.advance();
  ASSERT_EQ(headless.session().simulation().steps_taken(), steps);
  EXPECT_TRUE(threaded.session().simulation().positions() ==
              headless.session().simulation().positions())
      << "largest difference "
      << (threaded.session().simulation().positions() - headless.session().simulation().positions())
             .cwiseAbs()
             .maxCoeff();
  // The drag did move the cloth, so the comparison means something.
  EXPECT_GT(
      (headless.session().simulation().positions() - headless.session().scene().network.V).norm(),
      0.1);
  // The state drawn is the simulation's.
  const std::vector<float>& drawn = threaded.drawing().drawn_positions();
  const Eigen::MatrixXd& p = threaded.session().simulation().positions();
  EXPECT_EQ(drawn[3 * 100 + 1], static_cast<float>(p(100, 1)));
}

TEST(ViewerThread, WithAStepLimitItStopsThere) {
  const auto owner = cloth();
  wobble::Viewer& viewer = *owner;
  viewer.session().step_on_thread({});
  viewer.session().set_step_limit(7);
  double now = 0.0;
  for (int frame = 0; frame < 60000 && viewer.session().shown_steps() < 7;
       ++frame, now += frame_seconds) {
    viewer.exchange(now, frame_seconds);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  for (int frame = 0; frame < 20; ++frame, now += frame_seconds)
    viewer.exchange(now, frame_seconds);
  viewer.finish_steps();
  EXPECT_EQ(viewer.session().simulation().steps_taken(), 7);
  // Stopped there, it says so: paused (the page's frames=N froze the cloth mid-swing while the
  // button still said Pause), and Play goes on.
  EXPECT_TRUE(viewer.panel().paused());
  wobble::InputEvent space;
  space.type = wobble::InputEvent::Type::key_press;
  space.code = GLFW_KEY_SPACE;
  viewer.handle_events({space}, false, false, window);
  for (int frame = 0; frame < 60000 && viewer.session().shown_steps() < 10;
       ++frame, now += frame_seconds) {
    viewer.exchange(now, frame_seconds);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  viewer.finish_steps();
  EXPECT_GE(viewer.session().simulation().steps_taken(), 10);
}

// While a batch is out, a reset and a Ctrl+click wait for it, then happen in the order done:
// reset first keeps the new pin, the other way round the reset drops it.
TEST(ViewerThread, ChangesDuringABatchWaitAndKeepTheirOrder) {
  for (const bool reset_first : {true, false}) {
    SCOPED_TRACE(reset_first ? "R, then Ctrl+click" : "Ctrl+click, then R");
    const auto owner = cloth();
    wobble::Viewer& viewer = *owner;
    viewer.session().step_on_thread({});
    const int vertex = 40 * 20 + 20;  // the middle of the cloth, free
    const Eigen::Vector2f at = on_screen(viewer, vertex);
    const int pins = viewer.session().stats().pins;
    ASSERT_TRUE(viewer.exchange(0.0, frame_seconds));  // a batch starts
    if (reset_first) press_key(viewer, GLFW_KEY_R);
    control_click(viewer, at);
    if (!reset_first) press_key(viewer, GLFW_KEY_R);
    // Until the batch is taken, the panel shows the state it started from.
    EXPECT_EQ(viewer.session().stats().pins, pins);
    EXPECT_EQ(viewer.session().stats().steps, 0);
    viewer.finish_steps();
    EXPECT_EQ(viewer.session().simulation().steps_taken(), 0) << "the reset came after the step";
    EXPECT_EQ(viewer.session().simulation().is_pinned(vertex), reset_first);
    EXPECT_EQ(viewer.session().stats().pins, reset_first ? pins + 1 : pins);
  }
}

TEST(ViewerThread, ADragDuringBatchesMovesThePinOnceTheyFinish) {
  const auto owner = cloth();
  wobble::Viewer& viewer = *owner;
  viewer.session().step_on_thread({});
  const int corner = viewer.session().scene().pins[0];
  const Eigen::Vector2f at = on_screen(viewer, corner);
  const Eigen::Vector3d start = viewer.session().simulation().positions().row(corner);
  double now = 0.0;
  viewer.exchange(now, frame_seconds);
  InputEvent event;
  event.x = at.x();
  event.y = at.y();
  event.type = InputEvent::Type::cursor_move;
  viewer.handle_events({event}, false, false, window);
  event.type = InputEvent::Type::button_press;
  event.code = GLFW_MOUSE_BUTTON_LEFT;
  viewer.handle_events({event}, false, false, window);
  // A second press while holding is not a new gesture (one at a time), even before the grab
  // reached the simulation.
  EXPECT_TRUE(viewer.animating());
  for (int i = 1; i <= 20; ++i) {
    event.type = InputEvent::Type::cursor_move;
    event.x = at.x() + 10.0f * i;
    viewer.handle_events({event}, false, false, window);
    now += frame_seconds;
    viewer.exchange(now, frame_seconds);
  }
  event.type = InputEvent::Type::button_release;
  viewer.handle_events({event}, false, false, window);
  viewer.finish_steps();
  EXPECT_TRUE(viewer.session().simulation().is_pinned(corner));
  const Eigen::Vector3d target = viewer.session().simulation().pin_target(corner);
  EXPECT_GT((target - start).norm(), 0.3) << "the last move reached the simulation";
  // The next step takes the corner there: where the cursor let go.
  viewer.advance();
  EXPECT_NEAR((on_screen(viewer, corner) - at).x(), 200.0f, 3.0f);
}

}  // namespace

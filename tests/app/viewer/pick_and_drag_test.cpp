// PickAndDrag on its own, on a picture it is handed (no viewer, no GL): a press on a pin grabs
// it and a move drags its target, through the context's change; a press on empty space orbits;
// Ctrl toggles a pin; the wheel zooms unless the panel has the mouse; the marks show the pin
// under the cursor.
#include "app/viewer/pick_and_drag.h"

#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <functional>
#include <vector>

#include "app/interaction/picking.h"
#include "sim/shapes/builtin_scenes.h"

namespace {

using wobble::InputEvent;

struct Picture {
  Picture()
      : scene(wobble::make_builtin_scene("cloth")),
        simulation(scene.network, scene.pins, scene.params),
        camera(std::nullopt, std::nullopt) {
    camera.open(scene.look, scene.network.V, 0.0f);
    const Eigen::MatrixXd& V = simulation.positions();
    for (Eigen::Index i = 0; i < V.rows(); ++i) {
      for (int c = 0; c < 3; ++c)
        positions.push_back(static_cast<float>(V(i, c)));
      pinned.push_back(simulation.is_pinned(static_cast<int>(i)));
    }
    camera.frame(positions, 0.0f, wobble::ViewportRegion(), size.x() / size.y());
  }
  wobble::PointerContext context() {
    wobble::PointerContext context{wobble::PointerView(), camera, simulation};
    context.picture.view = wobble::view_matrix(camera.camera());
    context.picture.projection = wobble::projection_matrix(camera.camera(), size.x() / size.y());
    context.picture.positions = &positions;
    context.picture.pinned = &pinned;
    context.picture.size = size;
    // The viewer's change between batches: at once.
    context.change = [this](std::function<void(wobble::Simulation&)> what) {
      ++changes;
      what(simulation);
    };
    return context;
  }
  // Where vertex v is drawn, in window units.
  Eigen::Vector2f on_screen(int v) {
    const wobble::PointerContext c = context();
    const Eigen::Vector3f point(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
    const std::optional<Eigen::Vector3f> at =
        wobble::project_to_window(c.picture.projection * c.picture.view, point, size);
    return at ? Eigen::Vector2f(at->x(), at->y()) : Eigen::Vector2f(-1.0f, -1.0f);
  }

  wobble::Scene scene;
  wobble::Simulation simulation;
  wobble::ViewCamera camera;
  std::vector<float> positions;
  std::vector<unsigned char> pinned;
  Eigen::Vector2f size = Eigen::Vector2f(1280.0f, 720.0f);
  int changes = 0;
};

InputEvent event(InputEvent::Type type, const Eigen::Vector2f& at, bool control = false) {
  InputEvent e;
  e.type = type;
  e.code = GLFW_MOUSE_BUTTON_LEFT;
  e.control = control;
  e.x = at.x();
  e.y = at.y();
  return e;
}

TEST(PickAndDrag, APressOnAPinGrabsItAndAMoveDragsItsTarget) {
  Picture p;
  wobble::PickAndDrag mouse;
  const int pin = p.simulation.pinned_vertices().front();
  const Eigen::Vector2f at = p.on_screen(pin);
  wobble::PointerContext context = p.context();
  mouse.begin_events(false);
  EXPECT_FALSE(mouse.mouse_event(event(InputEvent::Type::cursor_move, at), context))
      << "moving over it takes nothing";
  std::vector<unsigned char> marks;
  mouse.mark(context.picture, marks);
  EXPECT_EQ(marks[pin], 2) << "the pin under the cursor";

  EXPECT_TRUE(mouse.mouse_event(event(InputEvent::Type::button_press, at), context));
  EXPECT_TRUE(mouse.holds());
  EXPECT_EQ(mouse.held_vertex(), pin);
  const Eigen::Vector3d before = p.simulation.pin_target(pin);
  mouse.mouse_event(event(InputEvent::Type::cursor_move, at + Eigen::Vector2f(0.0f, 80.0f)),
                    context);
  EXPECT_LT(p.simulation.pin_target(pin).y(), before.y() - 0.01) << "dragged down the screen";
  EXPECT_TRUE(mouse.mouse_event(event(InputEvent::Type::button_release, at), context));
  EXPECT_FALSE(mouse.holds());
  EXPECT_TRUE(p.simulation.is_pinned(pin)) << "a pin stays a pin";
}

TEST(PickAndDrag, EmptySpaceOrbitsAndTheWheelZoomsUnlessThePanelHasTheMouse) {
  Picture p;
  wobble::PickAndDrag mouse;
  wobble::PointerContext context = p.context();
  const Eigen::Vector2f corner(5.0f, 5.0f);  // nothing drawn there
  mouse.begin_events(false);
  mouse.mouse_event(event(InputEvent::Type::cursor_move, corner), context);
  const float yaw = p.camera.camera().yaw;
  EXPECT_TRUE(mouse.mouse_event(event(InputEvent::Type::button_press, corner), context));
  EXPECT_FALSE(mouse.holds());
  mouse.mouse_event(event(InputEvent::Type::cursor_move, corner + Eigen::Vector2f(100.0f, 0.0f)),
                    context);
  EXPECT_NE(p.camera.camera().yaw, yaw);
  mouse.mouse_event(event(InputEvent::Type::button_release, corner), context);
  EXPECT_EQ(p.changes, 0) << "the camera is not the simulation's";

  InputEvent wheel = event(InputEvent::Type::scroll, corner);
  wheel.y = 1.0;
  const float distance = p.camera.camera().distance;
  mouse.begin_events(/*ui_wants_mouse=*/true);
  EXPECT_FALSE(mouse.mouse_event(wheel, context));
  EXPECT_EQ(p.camera.camera().distance, distance);
  mouse.begin_events(false);
  EXPECT_TRUE(mouse.mouse_event(wheel, context));
  EXPECT_LT(p.camera.camera().distance, distance) << "a notch up comes closer";
}

TEST(PickAndDrag, CtrlClickTogglesAPin) {
  Picture p;
  wobble::PickAndDrag mouse;
  wobble::PointerContext context = p.context();
  const int free_vertex = 800;  // the middle of the 40x40 cloth
  ASSERT_FALSE(p.simulation.is_pinned(free_vertex));
  const Eigen::Vector2f at = p.on_screen(free_vertex);
  mouse.begin_events(false);
  mouse.mouse_event(event(InputEvent::Type::cursor_move, at), context);
  EXPECT_TRUE(mouse.mouse_event(event(InputEvent::Type::button_press, at, true), context));
  mouse.mouse_event(event(InputEvent::Type::button_release, at, true), context);
  EXPECT_TRUE(p.simulation.is_pinned(free_vertex));
}

}  // namespace

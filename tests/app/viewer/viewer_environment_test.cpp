// The viewer's environment controls in-process and without GL: Alt+drag moves a collider, W the
// wind, C hides the colliders, and the ground grid sits below what the scene reaches.
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "../../shared_constants.h"
#include "app/interaction/collider_picking.h"
#include "app/interaction/picking.h"
#include "app/viewer/viewer.h"
#include "sim/contact/collider_contact_term.h"

namespace {

using wobble::InputEvent;

using wobble::testing::window;

// The built-in cloth (flat at y = 1.2, pinned at two corners) with a sphere under its middle.
wobble::Scene cloth_over_a_sphere() {
  wobble::Scene scene = wobble::make_builtin_scene("cloth");
  wobble::Collider sphere;
  sphere.type = wobble::ColliderType::sphere;
  const Eigen::Vector3d middle = scene.network.V.colwise().mean().transpose();
  sphere.center = middle - Eigen::Vector3d(0.0, 0.6, 0.0);
  sphere.radius = 0.25;
  scene.params.contact.colliders.push_back(sphere);
  return scene;
}

struct Fixture {
  explicit Fixture(wobble::Scene scene)
      : viewer(std::move(scene), wobble::ViewerSettings(), wobble::builtin_scene_names()) {
    viewer.render(1280, 720, window, 1.0f);
  }
  Eigen::Vector2f on_screen(const Eigen::Vector3d& point) const {
    const Eigen::Matrix4f view_projection =
        wobble::projection_matrix(viewer.drawing().camera(), window.x() / window.y()) *
        wobble::view_matrix(viewer.drawing().camera());
    return wobble::project_to_window(view_projection, point.cast<float>(), window)->head<2>();
  }
  void send(InputEvent::Type type, const Eigen::Vector2f& at, int code = 0, bool alt = false) {
    InputEvent event;
    event.type = type;
    event.code = code;
    event.alt = alt;
    event.x = at.x();
    event.y = at.y();
    viewer.handle_events({event}, false, false, window);
  }
  void press_key(int key) {
    InputEvent event;
    event.type = InputEvent::Type::key_press;
    event.code = key;
    viewer.handle_events({event}, false, false, window);
  }
  Eigen::Vector3d sphere_center() const {
    return wobble::colliders_in(viewer.session().simulation().terms())[0].center;
  }
  wobble::Viewer viewer;
};

TEST(ViewerEnvironment, AltDragMovesTheSphereInThePlaneFacingTheCamera) {
  Fixture f(cloth_over_a_sphere());
  const Eigen::Vector3d start = f.sphere_center();
  const Eigen::Vector2f at = f.on_screen(start);
  // The point of the sphere's surface under the cursor.
  const wobble::Ray ray = wobble::cursor_ray(
      wobble::view_matrix(f.viewer.drawing().camera()),
      wobble::projection_matrix(f.viewer.drawing().camera(), window.x() / window.y()), at, window);
  const auto grabbed =
      wobble::pick_collider(ray, wobble::colliders_in(f.viewer.session().simulation().terms()));
  ASSERT_TRUE(grabbed);
  f.send(InputEvent::Type::cursor_move, at);
  f.send(InputEvent::Type::button_press, at, GLFW_MOUSE_BUTTON_LEFT, /*alt=*/true);
  for (int i = 1; i <= 10; ++i) {
    f.send(InputEvent::Type::cursor_move, at + Eigen::Vector2f(15.0f * i, 0.0f), 0, true);
    f.viewer.advance();
    f.viewer.render(1280, 720, window, 1.0f);
  }
  f.send(InputEvent::Type::button_release, at, GLFW_MOUSE_BUTTON_LEFT, true);
  const Eigen::Vector3d moved = f.sphere_center();
  // The grabbed surface point followed the cursor 150 px to the right, in the plane facing the
  // camera.
  const Eigen::Vector3d grabbed_now = grabbed->point.cast<double>() + (moved - start);
  EXPECT_NEAR((f.on_screen(grabbed_now) - at).x(), 150.0f, 1.0f);
  EXPECT_NEAR((f.on_screen(grabbed_now) - at).y(), 0.0f, 1.0f);
  EXPECT_NEAR(
      (moved - start).cast<float>().dot(wobble::camera_forward(f.viewer.drawing().camera())), 0.0f,
      1e-4f);
  EXPECT_GT((moved - start).norm(), 0.2);
  // The camera did not orbit, and the cloth was not grabbed.
  EXPECT_EQ(f.viewer.session().simulation().pin_count(), 2);
  // After release, moving the mouse moves nothing.
  f.send(InputEvent::Type::cursor_move, at, 0, true);
  EXPECT_EQ(f.sphere_center(), moved);
  // Reset puts the sphere back.
  f.press_key(GLFW_KEY_R);
  EXPECT_EQ(f.sphere_center(), start);
}

TEST(ViewerEnvironment, WithoutAltOrWithTheCollidersHiddenTheSphereStays) {
  Fixture f(cloth_over_a_sphere());
  const Eigen::Vector3d start = f.sphere_center();
  const Eigen::Vector2f at = f.on_screen(start);
  const float yaw = f.viewer.drawing().camera().yaw;
  // A plain drag over the sphere orbits the camera.
  f.send(InputEvent::Type::cursor_move, at);
  f.send(InputEvent::Type::button_press, at, GLFW_MOUSE_BUTTON_LEFT);
  f.send(InputEvent::Type::cursor_move, at + Eigen::Vector2f(50, 0));
  f.send(InputEvent::Type::button_release, at, GLFW_MOUSE_BUTTON_LEFT);
  EXPECT_EQ(f.sphere_center(), start);
  EXPECT_NE(f.viewer.drawing().camera().yaw, yaw);

  f.viewer.render(1280, 720, window, 1.0f);
  EXPECT_GT(f.viewer.drawing().collider_mesh().triangle_count(), 0);
  EXPECT_TRUE(f.viewer.panel().layers().solids);
  f.press_key(GLFW_KEY_C);  // hide
  f.viewer.render(1280, 720, window, 1.0f);
  EXPECT_FALSE(f.viewer.panel().layers().solids);
  EXPECT_EQ(f.viewer.drawing().collider_mesh().triangle_count(), 0);
  const Eigen::Vector2f now = f.on_screen(start);
  f.send(InputEvent::Type::cursor_move, now);
  f.send(InputEvent::Type::button_press, now, GLFW_MOUSE_BUTTON_LEFT, true);
  f.send(InputEvent::Type::cursor_move, now + Eigen::Vector2f(80, 0), 0, true);
  f.send(InputEvent::Type::button_release, now, GLFW_MOUSE_BUTTON_LEFT, true);
  EXPECT_EQ(f.sphere_center(), start);
  f.press_key(GLFW_KEY_C);  // shown again
  EXPECT_TRUE(f.viewer.panel().layers().solids);
}

TEST(ViewerEnvironment, TheDrawnSphereFollowsTheCollider) {
  Fixture f(cloth_over_a_sphere());
  const auto mean = [&] {
    const wobble::ColliderTriangles& mesh = f.viewer.drawing().collider_mesh();
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int i = 0; i < mesh.vertex_count(); ++i)
      sum += Eigen::Vector3d(mesh.positions[3 * i], mesh.positions[3 * i + 1],
                             mesh.positions[3 * i + 2]);
    return Eigen::Vector3d(sum / mesh.vertex_count());
  };
  const Eigen::Vector3d before = mean();
  EXPECT_NEAR((before - f.sphere_center()).norm(), 0.0, 1e-5);
  const Eigen::Vector2f at = f.on_screen(f.sphere_center());
  f.send(InputEvent::Type::cursor_move, at);
  f.send(InputEvent::Type::button_press, at, GLFW_MOUSE_BUTTON_LEFT, true);
  f.send(InputEvent::Type::cursor_move, at + Eigen::Vector2f(0, -100), 0, true);
  f.viewer.render(1280, 720, window, 1.0f);
  EXPECT_GT(mean().y(), before.y() + 0.05);
  EXPECT_NEAR((mean() - f.sphere_center()).norm(), 0.0, 1e-5);
}

TEST(ViewerEnvironment, WTogglesTheWindAndETheWireframe) {
  Fixture f(wobble::make_builtin_scene("cloth"));
  ASSERT_FALSE(f.viewer.session().simulation().params().wind.on);
  f.press_key(GLFW_KEY_W);
  const wobble::WindParams& wind = f.viewer.session().simulation().params().wind;
  EXPECT_TRUE(wind.on);
  EXPECT_TRUE(wind.velocity.isApprox(wobble::WindParams::default_breeze().velocity));
  EXPECT_FALSE(f.viewer.panel().layers().wireframe);  // W no longer toggles the wireframe
  f.press_key(GLFW_KEY_W);
  EXPECT_FALSE(f.viewer.session().simulation().params().wind.on);
  f.press_key(GLFW_KEY_E);
  EXPECT_TRUE(f.viewer.panel().layers().wireframe);
}

TEST(ViewerEnvironment, TheGroundIsBelowTheHangingClothOrAtTheGroundCollider) {
  const wobble::Scene cloth = wobble::make_builtin_scene("cloth");
  const double rest_lowest = cloth.network.V.col(1).minCoeff();
  Fixture free_hanging(cloth);
  // The 1 m cloth hangs from its corners at 1.2 m: its far edge can swing down about 1 m.
  EXPECT_LT(free_hanging.viewer.drawing().ground().height, rest_lowest - 1.0);

  wobble::Scene on_ground = cloth;
  wobble::Collider ground;
  ground.height = 0.4;
  on_ground.params.contact.colliders.push_back(ground);
  Fixture with_ground(on_ground);
  EXPECT_FLOAT_EQ(with_ground.viewer.drawing().ground().height, 0.4f);
  EXPECT_EQ(with_ground.viewer.drawing().collider_mesh().triangle_count(), 0);  // drawn as the grid
}

}  // namespace

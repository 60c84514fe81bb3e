// ViewCamera on its own: a scene's own view, framing the shape when asked, O back to the opening
// view, and the mouse kept within the limits.
#include "app/viewer/view_camera.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "sim/shapes/builtin_scenes.h"

namespace {

std::vector<float> flat(const Eigen::MatrixXd& V) {
  std::vector<float> positions;
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    for (int c = 0; c < 3; ++c)
      positions.push_back(static_cast<float>(V(i, c)));
  return positions;
}

TEST(ViewCamera, FramesTheShapeAndORestoresTheOpeningView) {
  const wobble::Scene scene = wobble::make_builtin_scene("cloth");
  wobble::ViewCamera camera(std::nullopt, std::nullopt);
  camera.open(scene.look, scene.network.V, 0.0f);
  const std::vector<float> positions = flat(scene.network.V);
  camera.frame(positions, 0.0f, wobble::ViewportRegion(), 16.0f / 9.0f);
  // Aimed at the shape and the room it may fall into, down to the ground.
  Eigen::Vector3d lower = scene.network.V.colwise().minCoeff().transpose();
  const Eigen::Vector3d upper = scene.network.V.colwise().maxCoeff().transpose();
  lower.y() = std::min(lower.y(), 0.0);
  const Eigen::Vector3f centre = (0.5 * (lower + upper)).cast<float>();
  EXPECT_LT((camera.camera().target - centre).norm(), 0.05f) << camera.camera().target.transpose();
  const wobble::OrbitCamera opened = camera.camera();

  camera.orbit(300.0f, -100.0f, 720.0f);
  camera.zoom(3.0f);
  EXPECT_NE(camera.camera().yaw, opened.yaw);
  camera.restore_opening_view();
  camera.frame(positions, 0.0f, wobble::ViewportRegion(), 16.0f / 9.0f);
  EXPECT_NEAR(camera.camera().yaw, opened.yaw, 1e-6f);
  EXPECT_NEAR(camera.camera().pitch, opened.pitch, 1e-6f);
  EXPECT_NEAR(camera.camera().distance, opened.distance, 1e-4f * opened.distance);
}

TEST(ViewCamera, ASceneWithItsOwnCameraOpensThereAndTheMouseStaysWithinTheLimits) {
  wobble::Scene scene = wobble::make_builtin_scene("cloth");
  scene.look.camera_position = Eigen::Vector3d(0.0, 1.0, 4.0);
  scene.look.camera_target = Eigen::Vector3d(0.0, 1.0, 0.0);
  wobble::ViewCamera camera(std::nullopt, std::nullopt);
  camera.open(scene.look, scene.network.V, 0.0f);
  EXPECT_NEAR(camera.camera().distance, 4.0f, 1e-5f);
  EXPECT_NEAR(camera.camera().target.y(), 1.0f, 1e-6f);

  for (int i = 0; i < 200; ++i)
    camera.zoom(-5.0f);  // as far out as the wheel goes
  EXPECT_LE(camera.camera().distance, camera.limits().max_distance * 1.0001f);
  // Turned down and up as far as the mouse goes: never under the ground.
  for (const float dy : {-400.0f, 400.0f}) {
    for (int i = 0; i < 50; ++i)
      camera.orbit(0.0f, dy, 720.0f);
    EXPECT_GE(wobble::camera_eye(camera.camera()).y(), camera.limits().lowest_eye - 1e-4f) << dy;
  }
}

}  // namespace

#include "render/camera.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace {

using wobble::OrbitCamera;

constexpr float pi = 3.14159265358979f;

// Window coordinates (pixels from the top-left) of a world point.
Eigen::Vector2f to_window(const OrbitCamera& camera, const Eigen::Vector3f& point, float width,
                          float height) {
  const Eigen::Vector4f clip = wobble::projection_matrix(camera, width / height) *
                               wobble::view_matrix(camera) * point.homogeneous();
  const Eigen::Vector2f ndc = clip.head<2>() / clip.w();
  return Eigen::Vector2f(0.5f * (ndc.x() + 1.0f) * width, 0.5f * (1.0f - ndc.y()) * height);
}

OrbitCamera some_camera() {
  OrbitCamera camera;
  camera.target = Eigen::Vector3f(0.3f, 1.0f, -0.2f);
  camera.distance = 2.5f;
  camera.yaw = 0.6f;
  camera.pitch = 0.3f;
  return camera;
}

TEST(Camera, EyeIsDistanceAwayAndLooksAtTarget) {
  const OrbitCamera camera = some_camera();
  const Eigen::Vector3f eye = wobble::camera_eye(camera);
  EXPECT_NEAR((eye - camera.target).norm(), camera.distance, 1e-5f);
  EXPECT_GT(eye.y(), camera.target.y());  // positive pitch looks down from above
  // In eye coordinates the target lies straight ahead on -z.
  const Eigen::Vector4f target = wobble::view_matrix(camera) * camera.target.homogeneous();
  EXPECT_NEAR(target.x(), 0.0f, 1e-5f);
  EXPECT_NEAR(target.y(), 0.0f, 1e-5f);
  EXPECT_NEAR(target.z(), -camera.distance, 1e-5f);
}

TEST(Camera, ZeroAnglesLookFromPlusZWithYUp) {
  OrbitCamera camera;
  camera.distance = 4.0f;
  EXPECT_TRUE(wobble::camera_eye(camera).isApprox(Eigen::Vector3f(0, 0, 4)));
  // A point above the target appears above the centre of the window.
  const Eigen::Vector2f up = to_window(camera, Eigen::Vector3f(0, 0.5f, 0), 800, 600);
  EXPECT_NEAR(up.x(), 400.0f, 1e-3f);
  EXPECT_LT(up.y(), 300.0f);
  // +x appears to the right.
  EXPECT_GT(to_window(camera, Eigen::Vector3f(0.5f, 0, 0), 800, 600).x(), 400.0f);
}

TEST(Camera, ViewMatrixIsARigidMotion) {
  const Eigen::Matrix4f view = wobble::view_matrix(some_camera());
  const Eigen::Matrix3f rotation = view.topLeftCorner<3, 3>();
  EXPECT_TRUE((rotation * rotation.transpose()).isIdentity(1e-5f));
  EXPECT_NEAR(rotation.determinant(), 1.0f, 1e-5f);
}

TEST(Camera, ProjectionPutsTheFieldOfViewAtTheWindowEdges) {
  OrbitCamera camera;
  camera.distance = 2.0f;
  camera.vertical_fov = pi / 2;  // 45° either side of the axis
  // At distance 2, a point 2 above the axis is at the top edge.
  const Eigen::Vector2f top = to_window(camera, Eigen::Vector3f(0, 2.0f, 0), 640, 480);
  EXPECT_NEAR(top.y(), 0.0f, 1e-3f);
  // Horizontally the field widens by the aspect ratio.
  const Eigen::Vector2f right =
      to_window(camera, Eigen::Vector3f(2.0f * 640 / 480, 0, 0), 640, 480);
  EXPECT_NEAR(right.x(), 640.0f, 1e-2f);
}

TEST(Camera, OrbitTurnsByPiPerWindowHeightAndClampsPitch) {
  OrbitCamera camera = some_camera();
  const float yaw = camera.yaw;
  wobble::orbit_camera(camera, 100.0f, 0.0f, 400.0f);
  EXPECT_NEAR(camera.yaw, yaw - pi / 4, 1e-5f);
  wobble::orbit_camera(camera, 0.0f, 10000.0f, 400.0f);
  EXPECT_FLOAT_EQ(camera.pitch, OrbitCamera::max_pitch);
  wobble::orbit_camera(camera, 0.0f, -20000.0f, 400.0f);
  EXPECT_FLOAT_EQ(camera.pitch, -OrbitCamera::max_pitch);
  // The target and distance stay put while orbiting.
  EXPECT_TRUE(camera.target.isApprox(some_camera().target));
  EXPECT_FLOAT_EQ(camera.distance, some_camera().distance);
}

TEST(Camera, PanKeepsThePointUnderTheCursorAtTargetDepth) {
  OrbitCamera camera = some_camera();
  const float width = 800, height = 600;
  const Eigen::Vector3f point = camera.target;
  const Eigen::Vector2f before = to_window(camera, point, width, height);
  wobble::pan_camera(camera, 37.0f, -21.0f, height);
  const Eigen::Vector2f after = to_window(camera, point, width, height);
  EXPECT_NEAR(after.x() - before.x(), 37.0f, 1e-2f);
  EXPECT_NEAR(after.y() - before.y(), -21.0f, 1e-2f);
}

TEST(Camera, ZoomDividesTheDistanceAndStaysInRange) {
  OrbitCamera camera = some_camera();
  wobble::zoom_camera(camera, 2.0f);
  EXPECT_NEAR(camera.distance, 2.5f / (1.15f * 1.15f), 1e-5f);
  wobble::zoom_camera(camera, -1.0f);
  EXPECT_NEAR(camera.distance, 2.5f / 1.15f, 1e-5f);
  wobble::zoom_camera(camera, 1e4f);
  EXPECT_FLOAT_EQ(camera.distance, OrbitCamera::min_distance);
  wobble::zoom_camera(camera, -1e4f);
  EXPECT_FLOAT_EQ(camera.distance, OrbitCamera::max_distance);
}

TEST(Camera, FrameBoxShowsEveryCornerOfTheBox) {
  for (const float aspect : {0.5f, 1.0f, 16.0f / 9.0f}) {
    OrbitCamera camera = some_camera();
    const Eigen::Vector3f lower(-3, 10, 2), upper(1, 11, 4);
    wobble::frame_box(camera, lower, upper, aspect);
    EXPECT_TRUE(camera.target.isApprox(0.5f * (lower + upper)));
    EXPECT_FLOAT_EQ(camera.yaw, some_camera().yaw);  // the direction of view is kept
    const float height = 500, width = aspect * height;
    float nearest_edge = width;
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3f p((corner & 1) ? upper.x() : lower.x(),
                              (corner & 2) ? upper.y() : lower.y(),
                              (corner & 4) ? upper.z() : lower.z());
      const Eigen::Vector2f at = to_window(camera, p, width, height);
      ASSERT_GE(at.x(), 0.0f) << "aspect " << aspect;
      ASSERT_LE(at.x(), width) << "aspect " << aspect;
      ASSERT_GE(at.y(), 0.0f) << "aspect " << aspect;
      ASSERT_LE(at.y(), height) << "aspect " << aspect;
      nearest_edge = std::min({nearest_edge, at.x(), width - at.x(), at.y(), height - at.y()});
    }
    // ... and is not framed absurdly loosely: some corner comes within a quarter of the window.
    EXPECT_LT(nearest_edge, 0.25f * std::min(width, height)) << "aspect " << aspect;
  }
}

TEST(Camera, FrameBoxIntoARegionCentresTheBoxThereAndFitsIt) {
  // The right 60% of a 16:9 view, as beside a panel on the left.
  const wobble::ViewportRegion region{0.4f, 0.0f, 1.0f, 1.0f};
  const float height = 450, width = 800;
  OrbitCamera camera = some_camera();
  const Eigen::Vector3f lower(-1, 0, -0.5f), upper(1, 1.5f, 0.5f);
  wobble::frame_box(camera, lower, upper, width / height, region);
  const Eigen::Vector2f centre = to_window(camera, 0.5f * (lower + upper), width, height);
  EXPECT_NEAR(centre.x(), 0.7f * width, 1e-2f);
  EXPECT_NEAR(centre.y(), 0.5f * height, 1e-2f);
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3f p((corner & 1) ? upper.x() : lower.x(),
                            (corner & 2) ? upper.y() : lower.y(),
                            (corner & 4) ? upper.z() : lower.z());
    const Eigen::Vector2f at = to_window(camera, p, width, height);
    EXPECT_GE(at.x(), region.left * width) << "corner " << corner;
    EXPECT_LE(at.x(), width) << "corner " << corner;
    EXPECT_GE(at.y(), 0.0f) << "corner " << corner;
    EXPECT_LE(at.y(), height) << "corner " << corner;
  }
  // Framing the whole view again puts the target back in the middle.
  wobble::frame_box(camera, lower, upper, width / height);
  EXPECT_TRUE(camera.lens_shift.isZero());
  EXPECT_NEAR(to_window(camera, camera.target, width, height).x(), 0.5f * width, 1e-2f);
}

TEST(Camera, OrbitStopsWithTheEyeAboveTheGround) {
  OrbitCamera camera = some_camera();  // target 1 m up, 2.5 m away
  const wobble::CameraLimits limits = wobble::camera_limits_for(1.0f, 0.0f);
  EXPECT_FLOAT_EQ(limits.lowest_eye, 0.05f);
  // Dragging far up turns the camera to look from below: it stops with the eye on the floor.
  wobble::orbit_camera(camera, 0.0f, -20000.0f, 400.0f, limits);
  EXPECT_NEAR(wobble::camera_eye(camera).y(), 0.05f, 1e-4f);
  EXPECT_LT(camera.pitch, 0.0f);  // a little below the target, which is above the ground
  // Turning about the vertical and upwards still works.
  const float yaw = camera.yaw;
  wobble::orbit_camera(camera, 50.0f, 100.0f, 400.0f, limits);
  EXPECT_NE(camera.yaw, yaw);
  EXPECT_GT(wobble::camera_eye(camera).y(), 0.3f);
}

TEST(Camera, AViewAlreadyBelowTheGroundMayRiseButNotSink) {
  OrbitCamera camera = some_camera();
  camera.pitch = -1.0f;  // eye at 1 − 2.5 sin 1 = −1.1 m, as --camera-pitch could ask
  const wobble::CameraLimits limits = wobble::camera_limits_for(1.0f, 0.0f);
  wobble::orbit_camera(camera, 30.0f, 0.0f, 400.0f, limits);
  EXPECT_FLOAT_EQ(camera.pitch, -1.0f);  // no jump when only turning
  wobble::orbit_camera(camera, 0.0f, -40.0f, 400.0f, limits);
  EXPECT_NEAR(camera.pitch, -1.0f, 1e-5f);  // no further down
  wobble::orbit_camera(camera, 0.0f, 40.0f, 400.0f, limits);
  EXPECT_NEAR(camera.pitch, -1.0f + pi / 10, 1e-5f);  // up as far as dragged
}

TEST(Camera, ZoomStopsShortOfTheShapeAndBeforeItIsADot) {
  OrbitCamera camera = some_camera();
  camera.pitch = 0.4f;
  const wobble::CameraLimits limits = wobble::camera_limits_for(1.0f, 0.0f);
  wobble::zoom_camera(camera, 100.0f, limits);
  EXPECT_FLOAT_EQ(camera.distance, 0.6f);
  wobble::zoom_camera(camera, -100.0f, limits);
  EXPECT_FLOAT_EQ(camera.distance, 20.0f);
  // A camera framed beyond the limit may come closer, but not go further.
  camera.distance = 30.0f;
  wobble::zoom_camera(camera, -1.0f, limits);
  EXPECT_FLOAT_EQ(camera.distance, 30.0f);
  wobble::zoom_camera(camera, 1.0f, limits);
  EXPECT_NEAR(camera.distance, 30.0f / 1.15f, 1e-4f);
}

TEST(Camera, BackingAwayWhileLookingUpTiltsToStayAboveTheGround) {
  OrbitCamera camera = some_camera();
  camera.pitch = -0.3f;  // eye at 1 − 2.5 sin 0.3 = 0.26 m
  const wobble::CameraLimits limits = wobble::camera_limits_for(1.0f, 0.0f);
  ASSERT_GT(wobble::camera_eye(camera).y(), limits.lowest_eye);
  wobble::zoom_camera(camera, -10.0f, limits);  // 4× further: the eye would be at −1.9 m
  EXPECT_GE(wobble::camera_eye(camera).y(), limits.lowest_eye - 1e-4f);
  EXPECT_NEAR(camera.distance, 2.5f * std::pow(1.15f, 10.0f), 1e-3f);
}

TEST(Camera, PanningDownStopsWithTheEyeOnTheFloor) {
  OrbitCamera camera = some_camera();
  const wobble::CameraLimits limits = wobble::camera_limits_for(1.0f, 0.0f);
  wobble::pan_camera(camera, 0.0f, -5000.0f, 400.0f, limits);  // drag up: the target goes down
  EXPECT_NEAR(wobble::camera_eye(camera).y(), limits.lowest_eye, 1e-4f);
  EXPECT_FLOAT_EQ(camera.pitch, some_camera().pitch);  // lifted, not turned
}

}  // namespace

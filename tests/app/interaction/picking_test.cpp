#include "app/interaction/picking.h"

#include <gtest/gtest.h>

#include <vector>

#include "render/camera.h"

namespace {

struct View {
  wobble::OrbitCamera camera;
  Eigen::Vector2f viewport{800.0f, 600.0f};
  Eigen::Matrix4f view() const { return wobble::view_matrix(camera); }
  Eigen::Matrix4f projection() const {
    return wobble::projection_matrix(camera, viewport.x() / viewport.y());
  }
  Eigen::Matrix4f view_projection() const { return projection() * view(); }
};

// Looking from +z at the origin, 3 m away.
View front_view() {
  View view;
  view.camera.distance = 3.0f;
  return view;
}

TEST(Picking, TargetProjectsToTheWindowCentre) {
  const View view = front_view();
  const auto at =
      wobble::project_to_window(view.view_projection(), Eigen::Vector3f::Zero(), view.viewport);
  ASSERT_TRUE(at);
  EXPECT_NEAR(at->x(), 400.0f, 1e-3f);
  EXPECT_NEAR(at->y(), 300.0f, 1e-3f);
  // Behind the eye there is nothing to see.
  EXPECT_FALSE(
      wobble::project_to_window(view.view_projection(), Eigen::Vector3f(0, 0, 5), view.viewport));
}

TEST(Picking, PicksWithinTheRadiusOnly) {
  const View view = front_view();
  const std::vector<float> positions = {0, 0, 0, 0.5f, 0, 0};
  const auto second =
      wobble::project_to_window(view.view_projection(), Eigen::Vector3f(0.5f, 0, 0), view.viewport);
  const Eigen::Vector2f near_second = second->head<2>() + Eigen::Vector2f(3, -4);  // 5 px off
  EXPECT_EQ(wobble::pick_vertex(view.view_projection(), positions.data(), 2, nullptr, near_second,
                                view.viewport, 6.0f),
            1);
  EXPECT_EQ(wobble::pick_vertex(view.view_projection(), positions.data(), 2, nullptr, near_second,
                                view.viewport, 4.0f),
            -1);
}

TEST(Picking, PrefersTheVertexNearestTheCameraAndHonoursEligibility) {
  const View view = front_view();
  // Three vertices on the line of sight through the centre: behind, middle, in front.
  const std::vector<float> positions = {0, 0, -1, 0, 0, 0, 0, 0, 1};
  const Eigen::Vector2f centre(400, 300);
  EXPECT_EQ(wobble::pick_vertex(view.view_projection(), positions.data(), 3, nullptr, centre,
                                view.viewport, 5.0f),
            2);
  const std::vector<unsigned char> pinned = {1, 1, 0};
  EXPECT_EQ(wobble::pick_vertex(view.view_projection(), positions.data(), 3, pinned.data(), centre,
                                view.viewport, 5.0f),
            1);
}

TEST(Picking, OnAnObliqueSheetPicksTheVertexClosestToTheCursor) {
  View view = front_view();
  view.camera.pitch = 0.35f;  // looking down at a horizontal sheet: rows crowd together on screen
  std::vector<float> positions;
  for (int row = 0; row < 5; ++row) {
    for (int column = 0; column < 5; ++column) {
      positions.insert(positions.end(), {0.02f * column, 0.0f, 0.02f * row});
    }
  }
  for (int i = 0; i < 25; ++i) {
    const auto at = wobble::project_to_window(view.view_projection(),
                                              Eigen::Map<const Eigen::Vector3f>(&positions[3 * i]),
                                              view.viewport);
    EXPECT_EQ(wobble::pick_vertex(view.view_projection(), positions.data(), 25, nullptr,
                                  at->head<2>(), view.viewport, 30.0f),
              i);
  }
}

TEST(Picking, CursorRayPassesThroughWhatIsDrawnUnderTheCursor) {
  View view = front_view();
  view.camera.yaw = 0.7f;
  view.camera.pitch = -0.2f;
  view.camera.target = Eigen::Vector3f(1, 2, 3);
  const Eigen::Vector3f point(1.4f, 1.7f, 2.5f);
  const auto at = wobble::project_to_window(view.view_projection(), point, view.viewport);
  ASSERT_TRUE(at);
  const wobble::Ray ray =
      wobble::cursor_ray(view.view(), view.projection(), at->head<2>(), view.viewport);
  EXPECT_NEAR(ray.direction.norm(), 1.0f, 1e-5f);
  // Distance from the point to the ray's line.
  const Eigen::Vector3f offset = point - ray.origin;
  EXPECT_NEAR((offset - offset.dot(ray.direction) * ray.direction).norm(), 0.0f, 1e-4f);
  EXPECT_GT(offset.dot(ray.direction), 0.0f);
}

TEST(Picking, DragPlaneFollowsTheCursorAtTheVertexDepth) {
  const View view = front_view();
  const Eigen::Vector3f vertex(0.2f, 0.1f, 0.5f);
  const Eigen::Vector3f normal = wobble::camera_forward(view.camera);
  // Move the cursor to where another point of the same plane is drawn: the ray meets the plane
  // exactly there.
  const Eigen::Vector3f goal = vertex + Eigen::Vector3f(-0.4f, 0.3f, 0.0f);
  const auto at = wobble::project_to_window(view.view_projection(), goal, view.viewport);
  const wobble::Ray ray =
      wobble::cursor_ray(view.view(), view.projection(), at->head<2>(), view.viewport);
  const auto hit = wobble::intersect_plane(ray, vertex, normal);
  ASSERT_TRUE(hit);
  EXPECT_TRUE(hit->isApprox(goal, 1e-4f)) << hit->transpose();
  // A ray running along the plane, or away from it, meets nothing.
  const wobble::Ray along{Eigen::Vector3f::Zero(), Eigen::Vector3f::UnitX()};
  EXPECT_FALSE(wobble::intersect_plane(along, vertex, normal));
  const wobble::Ray away{Eigen::Vector3f(0, 0, 3), Eigen::Vector3f::UnitZ()};
  EXPECT_FALSE(wobble::intersect_plane(away, vertex, normal));
}

}  // namespace

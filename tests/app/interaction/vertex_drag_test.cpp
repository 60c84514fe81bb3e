#include "app/interaction/vertex_drag.h"

#include <gtest/gtest.h>

#include "sim/shapes/cloth_grid.h"

namespace {

using wobble::Ray;
using wobble::Simulation;

// A small cloth lying in the xz plane, pinned at one corner, seen from straight above (the drag
// plane is then horizontal: y = the grabbed vertex's height).
struct Fixture {
  Fixture() {
    wobble::ClothGridOptions options;
    options.resolution = 6;
    simulation = std::make_unique<Simulation>(wobble::make_cloth_grid(options), std::vector<int>{0},
                                              wobble::SimulationParams{});
  }
  // The ray straight down onto (x, z).
  static Ray down_at(float x, float z) {
    return Ray{Eigen::Vector3f(x, 5.0f, z), Eigen::Vector3f(0.0f, -1.0f, 0.0f)};
  }
  std::unique_ptr<Simulation> simulation;
  const Eigen::Vector3f looking_down{0.0f, -1.0f, 0.0f};
};

TEST(VertexDrag, DraggingAPinMovesItsTargetWithoutRefactorizing) {
  Fixture f;
  wobble::VertexDrag drag;
  const Eigen::Vector3d start = f.simulation->positions().row(0);
  const int factorizations = f.simulation->numeric_factorizations();
  // Grab a little off the vertex: the offset is kept, so the target does not jump.
  drag.grab(*f.simulation, 0, Fixture::down_at(start.x() + 0.01f, start.z()), f.looking_down);
  EXPECT_TRUE(drag.active());
  EXPECT_FALSE(drag.holds_free_vertex());
  EXPECT_TRUE(f.simulation->pin_target(0).isApprox(start));

  drag.move(*f.simulation, Fixture::down_at(start.x() + 0.31f, start.z() - 0.2f));
  const Eigen::Vector3d expected = start + Eigen::Vector3d(0.3, 0.0, -0.2);
  EXPECT_TRUE(f.simulation->pin_target(0).isApprox(expected, 1e-6)) << f.simulation->pin_target(0);
  for (int i = 0; i < 3; ++i)
    f.simulation->step();
  // The pin weight (1e10) holds the vertex on its target.
  EXPECT_LT((Eigen::Vector3d(f.simulation->positions().row(0)) - expected).norm(), 1e-6);

  drag.release(*f.simulation);
  EXPECT_FALSE(drag.active());
  EXPECT_TRUE(f.simulation->is_pinned(0));  // it was a pin before, so it stays one
  EXPECT_EQ(f.simulation->numeric_factorizations(), factorizations);
}

TEST(VertexDrag, AFreeVertexIsHeldThenLetGoWithItsMotion) {
  Fixture f;
  wobble::VertexDrag drag;
  const int vertex = 35;  // the far corner
  ASSERT_FALSE(f.simulation->is_pinned(vertex));
  const Eigen::Vector3d start = f.simulation->positions().row(vertex);
  drag.grab(*f.simulation, vertex, Fixture::down_at(start.x(), start.z()), f.looking_down);
  EXPECT_TRUE(drag.holds_free_vertex());
  EXPECT_TRUE(f.simulation->is_pinned(vertex));

  // Flick it along +x, 2 cm per step.
  for (int i = 1; i <= 5; ++i) {
    drag.move(*f.simulation, Fixture::down_at(start.x() + 0.02f * i, start.z()));
    f.simulation->step();
  }
  drag.release(*f.simulation);
  EXPECT_FALSE(f.simulation->is_pinned(vertex));
  EXPECT_FALSE(drag.active());
  // Released, it keeps the velocity of the drag: 0.02 m per 1/60 s along x.
  const double speed = f.simulation->velocities()(vertex, 0);
  EXPECT_NEAR(speed, 0.02 * 60.0, 0.05) << "velocity after the flick";
}

TEST(VertexDrag, MoveAndReleaseWithoutAGrabChangeNothing) {
  Fixture f;
  wobble::VertexDrag drag;
  const Eigen::MatrixXd before = f.simulation->positions();
  drag.move(*f.simulation, Fixture::down_at(1, 1));
  drag.release(*f.simulation);
  EXPECT_EQ(f.simulation->pin_count(), 1);
  EXPECT_TRUE(f.simulation->positions().isApprox(before));
}

}  // namespace

namespace {

TEST(VertexDrag, ARayGrazingThePlaneKeepsTheTargetWithinReach) {
  Fixture f;
  wobble::VertexDrag drag;
  const Eigen::Vector3d start = f.simulation->positions().row(0);
  drag.grab(*f.simulation, 0, Fixture::down_at(start.x(), start.z()), f.looking_down);
  // Almost parallel to the horizontal plane: it meets it some 5e6 m away.
  const Ray grazing{Eigen::Vector3f(start.x(), start.y() + 5.0f, start.z()),
                    Eigen::Vector3f(1.0f, -1e-6f, 0.0f).normalized()};
  drag.move(*f.simulation, grazing);
  const double reach = wobble::VertexDrag::reach_in_jump_limits * f.simulation->jump_limit();
  const Eigen::Vector3d target = f.simulation->pin_target(0);
  EXPECT_NEAR((target - start).norm(), reach, 1e-3 * reach);
  EXPECT_GT(target.x() - start.x(), 0.99 * reach) << "still in the direction of the drag";
  EXPECT_EQ(f.simulation->step(), wobble::StepStatus::ok);
}

}  // namespace

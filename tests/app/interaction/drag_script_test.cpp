// --drag VERTEX:DX,DY,DZ@FRAME[-LAST]: parsing, and what a scripted drag does to a simulation.
#include "app/interaction/drag_script.h"

#include <gtest/gtest.h>

#include "../../sim/test_meshes.h"
#include "sim/input_error.h"

namespace {

using wobble::DragScript;
using wobble::InputError;
using wobble::parse_drag;
using wobble::ScriptedDrag;
using wobble::Simulation;
using wobble::SimulationParams;

TEST(DragScript, ParsesTheVertexTheOffsetAndTheFrames) {
  const ScriptedDrag one = parse_drag("12:0.5,-1,2e-1@7", 1000);
  EXPECT_EQ(one.vertex, 12);
  EXPECT_EQ(one.offset, Eigen::Vector3d(0.5, -1.0, 0.2));
  EXPECT_EQ(one.first_frame, 7);
  EXPECT_EQ(one.last_frame, 7 + ScriptedDrag::default_frames - 1);
  const ScriptedDrag range = parse_drag("0:0,0,1@3-3", 1000);
  EXPECT_EQ(range.first_frame, 3);
  EXPECT_EQ(range.last_frame, 3);
}

TEST(DragScript, RefusesMalformedDragsNamingTheOption) {
  for (const char* text : {"", "12", "12:1,2,3", "12@4", "x:1,2,3@4", "-1:1,2,3@4", "1:1,2@4",
                           "1:1,2,3,4@4", "1:1,nan,3@4", "1:1,2,1e7@4", "1:1,2,3@0", "1:1,2,3@4-2",
                           "1:1,2,3@4-", "1:1,2,3@2000", "1@2:1,2,3"}) {
    SCOPED_TRACE(text);
    try {
      parse_drag(text, 1000);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind("--drag: expected", 0), 0u) << message;
      EXPECT_NE(message.find(std::string("'") + text + "'"), std::string::npos) << message;
    }
  }
}

TEST(DragScript, RefusesAVertexTheSceneDoesNotHave) {
  EXPECT_NO_THROW(DragScript({parse_drag("3:0,0,1@1", 100)}, 4));
  EXPECT_THROW(DragScript({parse_drag("4:0,0,1@1", 100)}, 4), InputError);
}

TEST(DragScript, AFreeVertexIsHeldAlongTheWayAndLetGoAfter) {
  const auto mesh = wobble::testing::chain_mesh(3);
  SimulationParams params;
  params.gravity.setZero();
  Simulation simulation(mesh.network, mesh.pins, params);
  DragScript script({parse_drag("3:0,0.4,0@2-5", 100)}, 4);
  const Eigen::Vector3d start = mesh.network.V.row(3);
  for (long frame = 1; frame <= 7; ++frame) {
    script.before_step(simulation, frame);
    const bool held = frame >= 2 && frame <= 5;
    EXPECT_EQ(simulation.is_pinned(3), held) << "frame " << frame;
    if (held) {
      const Eigen::Vector3d expected = start + Eigen::Vector3d(0.0, 0.1 * (frame - 1), 0.0);
      EXPECT_LT((simulation.pin_target(3) - expected).norm(), 1e-12) << "frame " << frame;
      // Taken again, as after a rolled-back step: nothing changes.
      script.before_step(simulation, frame);
      EXPECT_LT((simulation.pin_target(3) - expected).norm(), 1e-12) << "frame " << frame;
    }
    simulation.step();
    if (held) {
      EXPECT_NEAR(simulation.positions()(3, 1), start.y() + 0.1 * (frame - 1), 1e-6);
    }
    if (frame == 5) {
      // Let go at the drag's speed, 0.1 m a frame upwards.
      EXPECT_NEAR(simulation.velocities()(3, 1), 0.1 / params.dt, 1e-3);
    }
  }
  EXPECT_EQ(simulation.pinned_vertices(), mesh.pins);
  // Free again: the springs have pulled it off the drag's end point.
  EXPECT_GT(std::abs(simulation.positions()(3, 1) - (start.y() + 0.4)), 1e-3);
}

TEST(DragScript, APinnedVertexStaysPinnedWhereTheDragLeftIt) {
  const auto mesh = wobble::testing::chain_mesh(2);
  Simulation simulation(mesh.network, mesh.pins, wobble::SimulationParams());
  const int pin = mesh.pins[0];
  DragScript script({parse_drag(std::to_string(pin) + ":0,0,-1@1-2", 100)}, 3);
  for (long frame = 1; frame <= 4; ++frame) {
    script.before_step(simulation, frame);
    simulation.step();
  }
  EXPECT_TRUE(simulation.is_pinned(pin));
  EXPECT_LT((simulation.pin_target(pin) - Eigen::Vector3d(mesh.network.V.row(pin)) -
             Eigen::Vector3d(0, 0, -1))
                .norm(),
            1e-12);
}

TEST(DragScript, RestartForgetsADragInProgress) {
  const auto mesh = wobble::testing::chain_mesh(2);
  Simulation simulation(mesh.network, mesh.pins, wobble::SimulationParams());
  DragScript script({parse_drag("2:1,0,0@1-10", 100)}, 3);
  script.before_step(simulation, 1);
  ASSERT_TRUE(simulation.is_pinned(2));
  simulation.reset();
  script.restart();
  EXPECT_FALSE(simulation.is_pinned(2));
  // From frame 1 again: taken again at the rest position.
  script.before_step(simulation, 1);
  EXPECT_LT((simulation.pin_target(2) - Eigen::Vector3d(mesh.network.V.row(2)) -
             Eigen::Vector3d(0.1, 0, 0))
                .norm(),
            1e-12);
}

}  // namespace

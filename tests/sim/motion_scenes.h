#ifndef WOBBLE_TESTS_SIM_MOTION_SCENES_H
#define WOBBLE_TESTS_SIM_MOTION_SCENES_H

#include <Eigen/Core>
#include <vector>

#include "sim/simulation.h"
#include "sim/spring_network.h"

namespace wobble::testing {

// Scenes that test how self-contact lets a cloth move, not only that it never crosses: a sheet
// in free air must fall as it falls without self-contact, and a sheet on another sheet must
// slide as it would on a collider of the same slope.
struct MotionScene {
  SpringNetwork network;
  std::vector<int> pins;
  SimulationParams params;
  std::vector<int> moving;  // the vertices of the sheet whose motion is measured
};

// Two n × n sheets, 1 m square, no bend springs: one lying on the ground (y = 0), the other
// (`moving`) 0.5 m above it, tilted 5° about x, let go at rest. 15 iterations, thickness 5 mm,
// friction 0.4, Δt = 1/60 s. The upper sheet falls freely for about 0.3 s before it meets the
// lower one.
MotionScene falling_sheets_scene(int n, bool self_collision);

// A 0.3 m sheet (10 × 10, `moving`) lying a thickness (5 mm) above a slope of `angle_degrees`
// about x, 0.9 m up it, at rest. The slope is either a 2.5 m sheet (26 × 26, every vertex
// pinned; self-contact keeps the two apart) or, with `on_plane`, a plane collider (the same
// offset of 5 mm, no self-contact). Coulomb friction `friction` against either. 30 iterations.
MotionScene sliding_sheet_scene(double angle_degrees, double friction, bool on_plane);

// The direction down the slope of sliding_sheet_scene (a unit vector).
Eigen::Vector3d slope_direction(double angle_degrees);

// The mean position of `vertices` in `positions` (#V by 3).
Eigen::Vector3d centroid(const Eigen::MatrixXd& positions, const std::vector<int>& vertices);

}  // namespace wobble::testing

#endif

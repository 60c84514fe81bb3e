#ifndef WOBBLE_TESTS_SIM_FOLDING_SCENES_H
#define WOBBLE_TESTS_SIM_FOLDING_SCENES_H

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "sim/contact/self_collision.h"
#include "sim/simulation.h"
#include "sim/spring_network.h"

namespace wobble::testing {

// A scene in which a cloth folds onto itself, for the self-collision tests: start a Simulation
// from `network`, `pins`, `params` and `initial_velocity` (#V by 3 m/s, or empty for rest), then
// call `before_step(simulation, step)` before each of `steps` steps (it moves the pin targets).
// All three use k = 1000 N/m, Δt = 1/60 s, 30 iterations, friction 0.4, damping 0.05 /s,
// areal density 0.25 kg/m², and `self_collision` as given.
struct FoldingScene {
  std::string name;
  SpringNetwork network;
  std::vector<int> pins;
  SimulationParams params;
  Eigen::MatrixXd initial_velocity;
  int steps = 0;
  std::function<void(Simulation&, int step)> before_step;
};

// A 32 × 32 cloth, 1 m square, held upright with its lower edge 3 cm above the ground (y = 0)
// and let go with a sideways velocity that varies along it, so that it buckles and falls into a
// pile of folds on the ground. 300 steps (5 s).
FoldingScene cloth_pile_scene(const SelfCollisionParams& self_collision);

// A 32 × 32 cloth, 1 m square, flat on the ground; its whole first row (an edge) is pinned,
// lifted and carried over the cloth along a half circle to beyond the opposite edge in 2 s, so
// that the cloth folds in half over itself; then held there 1 s. 180 steps.
FoldingScene dragged_across_scene(const SelfCollisionParams& self_collision);

// A strip of 8 × 80 vertices (0.23 m by 2.6 m) hanging from its pinned end beside a sphere
// (radius 0.2 m); the pinned end is carried twice around the sphere in a vertical circle in 8 s,
// so the strip's weight winds it around the sphere twice, layer over layer; then held 1 s. No
// ground; 50 iterations. 540 steps.
FoldingScene sphere_wrap_scene(const SelfCollisionParams& self_collision);

}  // namespace wobble::testing

#endif

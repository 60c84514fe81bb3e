#ifndef WOBBLE_TESTS_BENCHMARK_SELF_COLLISION_COST_H
#define WOBBLE_TESTS_BENCHMARK_SELF_COLLISION_COST_H

#include <Eigen/Core>

#include "sim/settings/simulation_params.h"
#include "sim/spring_network.h"

namespace wobble::benchmark {

// A free n×n cloth (1 m, no bend springs) standing on its lower edge 5 cm above the ground
// (row 0 on top), pleated along x and thrown down edge first with a buckling push across its
// plane, so that it folds over itself into a pile: the benchmark's piles. 15 iterations,
// thickness 5 mm, friction 0.4, damping 0.2 /s, the given solver.
struct ThrownPile {
  SpringNetwork cloth;
  Eigen::MatrixXd velocity;  // #V by 3 (m/s)
  SimulationParams params;
};
ThrownPile thrown_pile(int n, bool self_collision, const char* solver);

// Self-collision's cost, printed as table rows:
// - the 40×40 pile (a pleated cloth thrown down edge first, as the cloth_pile asset), with and
//   without self-collision, while it folds (steps 1–150) and once it lies still (steps
//   301–400): median step times and their ratio;
// - free 40×40, 128×128 and 256×256 cloths thrown down edge first onto the ground with a
//   sideways push (up to 90 frames, or a minute of stepping each): the median step with and
//   without self-collision, detection (and per vertex) and response, and peak memory;
// - a 128×128 cloth falling onto a ball on the ground, its skirt folding onto itself: the
//   median step and its detection and response parts.
void print_self_collision_cost();

}  // namespace wobble::benchmark

#endif

#include "volume_cost.h"

#include <cstdio>
#include <vector>

#include "median.h"
#include "sim/settings/setting_registry.h"
#include "sim/shapes/jelly_block.h"
#include "sim/simulation.h"

namespace wobble::benchmark {

namespace {

// The median total step time (ms) of steps 11 to 10 + `steps` of the block swaying, set off by a
// sideways push.
double median_step(const SpringNetwork& block, const std::vector<int>& pins,
                   const SimulationParams& params, int steps) {
  Eigen::MatrixXd push = Eigen::MatrixXd::Zero(block.V.rows(), 3);
  push.col(0) = 2.0 * block.V.col(1);  // m/s, growing with height
  Simulation simulation(block, pins, params, push);
  std::vector<double> total;
  for (int step = 0; step < 10 + steps; ++step) {
    simulation.step();
    if (step >= 10) total.push_back(simulation.last_step_timing().total_ms);
  }
  return median(total);
}

}  // namespace

void print_volume_cost() {
  std::printf("\nvolume term: median ms a step, 50 iterations, block with its base pinned\n");
  std::printf("%-12s %8s %-12s %10s %10s %7s\n", "resolution", "tets", "solver", "off (ms)",
              "on (ms)", "ratio");
  for (const int resolution : {8, 15}) {
    JellyBlockOptions options;
    options.resolution = resolution;
    const SpringNetwork block = make_jelly_block(options);
    std::vector<int> pins;
    const int base = (resolution + 1) * (resolution + 1);
    for (int i = 0; i < base; ++i)
      pins.push_back(i);
    const int steps = resolution <= 8 ? 40 : 10;
    for (const char* solver : {"local-global", "lbfgs"}) {
      SimulationParams params;
      params.k = 1500.0;
      params.solver = solver;
      const double off = median_step(block, pins, params, steps);
      set_setting_value(params, "volume-stiffness", 20000.0);
      const double on = median_step(block, pins, params, steps);
      std::printf("%-12d %8ld %-12s %10.2f %10.2f %6.2fx\n", resolution,
                  static_cast<long>(block.T.rows()), solver, off, on, on / off);
    }
  }
}

}  // namespace wobble::benchmark

#include "quantity_colors_cost.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "median.h"

#include "app/viewer/quantity_colors.h"
#include "sim/shapes/cloth_grid.h"
#include "sim/simulation.h"

namespace wobble::benchmark {

void print_quantity_colors_cost() {
  ClothGridOptions options;
  options.resolution = 128;
  options.size = 2.0;
  const SpringNetwork cloth = make_cloth_grid(options);
  // Pinned at the ends of row 0, the "top" edge, it falls from flat and swings: strains and
  // speeds vary over the cloth.
  const std::vector<int> pins = {0, options.resolution - 1};
  SimulationParams params;
  params.k = 400.0;
  params.iterations = 50;
  Simulation simulation(cloth, pins, params);
  std::vector<double> steps;
  for (int step = 0; step < 60; ++step) {  // a second of swinging: strains and speeds vary
    simulation.step();
    steps.push_back(simulation.last_step_timing().total_ms);
  }
  for (const ColorQuantity quantity : {ColorQuantity::strain, ColorQuantity::speed}) {
    for (const bool springs : {false, true}) {
      QuantityColors colors;
      std::vector<double> ms;
      for (int frame = 0; frame < 100; ++frame) {
        const auto start = std::chrono::steady_clock::now();
        colors.update(quantity, simulation, springs);
        ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
      }
      std::printf("colours/128x128 cloth %-6s %-13s  %.3f ms a frame (%.1f%% of a %.2f ms step)\n",
                  color_quantity_name(quantity), springs ? "with springs" : "surface only",
                  median(ms), 100.0 * median(ms) / median(steps), median(steps));
    }
  }
}

}  // namespace wobble::benchmark

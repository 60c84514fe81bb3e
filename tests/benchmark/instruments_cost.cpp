#include "instruments_cost.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "median.h"
#include "sim/instruments/frame_energy.h"
#include "sim/shapes/builtin_scenes.h"
#include "sim/shapes/cloth_grid.h"
#include "sim/simulation.h"

namespace wobble::benchmark {

namespace {

void print_row(const char* name, const SpringNetwork& network, const std::vector<int>& pins,
               SimulationParams params) {
  Simulation quiet(network, pins, params), recorded(network, pins, params);
  recorded.set_convergence_recording(true);
  std::vector<double> off, on, energy;
  for (int step = 0; step < 60; ++step) {
    // Alternating, so that a busy moment of the machine falls on both.
    quiet.step();
    recorded.step();
    if (step < 10) continue;  // let both leave rest first
    off.push_back(quiet.last_step_timing().total_ms);
    on.push_back(recorded.last_step_timing().total_ms);
    const auto start = std::chrono::steady_clock::now();
    volatile double total = frame_energy(quiet).total;  // kept, so the call is not optimized away
    (void)total;
    energy.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count());
  }
  const double step_off = median(off), step_on = median(on);
  std::printf(
      "instruments/%s%s  step %.2f ms  with trace %.2f ms (x%.3f)  frame energy %.3f ms "
      "(%.2f%%)\n",
      name, params.chebyshev ? " chebyshev" : "", step_off, step_on, step_on / step_off,
      median(energy), 100.0 * median(energy) / step_off);
}

}  // namespace

void print_instruments_cost() {
  const Scene cloth = make_builtin_scene("cloth");
  ClothGridOptions options;
  options.resolution = 128;
  const SpringNetwork large = make_cloth_grid(options);
  const std::vector<int> corners = {0, options.resolution - 1};
  for (const bool chebyshev : {false, true}) {
    SimulationParams params = cloth.params;
    params.chebyshev = chebyshev;
    print_row("cloth 40x40", cloth.network, cloth.pins, params);
    print_row("cloth 128x128", large, corners, params);
  }
}

}  // namespace wobble::benchmark

#include "self_collision_settling.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "io/load_scene.h"
#include "median.h"
#include "sim/instruments/frame_energy.h"
#include "sim/simulation.h"

namespace wobble::benchmark {

void print_self_collision_settling() {
  const Scene scene = load_scene(WOBBLE_ASSETS_DIR "/cloth_pile.json");
  std::printf(
      "| iterations | thickness | energy at the start | most over steps 300-899 | kinetic at "
      "step 900 | lying step (ms) | searches a step | settles |\n|---|---|---|---|---|---|---|---|"
      "\n");
  for (const double thickness : {0.01, 0.005}) {
    for (const int iterations : {50, 30, 20}) {
      SimulationParams params = scene.params;
      params.iterations = iterations;
      params.self_collision.on = true;
      params.self_collision.thickness = thickness;
      Simulation simulation(scene.network, scene.pins, params, scene.initial_velocity);
      const double start = frame_energy(simulation).total;
      double most = 0.0;
      std::vector<double> steps, searches;
      for (int step = 0; step < 900; ++step) {
        simulation.step();
        if (step >= 300) most = std::max(most, frame_energy(simulation).total);
        if (step >= 700) {
          const StepTiming& timing = simulation.last_step_timing();
          steps.push_back(timing.total_ms);
          searches.push_back(timing.figure("self-contact", "epochs"));
        }
      }
      const double kinetic = frame_energy(simulation).kinetic;
      // Settled: it never regained its starting energy once down, and barely moves at the end
      // (1e-3 J is a mean speed of about 9 cm/s for its 0.25 kg).
      const bool settles = most < start && kinetic < 1e-3;
      std::printf("| %d | %.3g m | %.3g J | %.3g J | %.3g J | %.1f | %.0f | %s |\n", iterations,
                  thickness, start, most, kinetic, median(steps), median(searches),
                  settles ? "yes" : "no");
      std::fflush(stdout);
    }
  }
}

}  // namespace wobble::benchmark

#include "self_collision_settling.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "io/load_scene.h"
#include "median.h"
#include "sim/folding_scenes.h"
#include "sim/instruments/frame_energy.h"
#include "sim/mesh_crossings.h"
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

void print_self_collision_landing() {
  std::printf(
      "| thickness | let go | most kinetic over steps 401-460 | the tests ask below | crossings "
      "when self-collision starts / at the end |\n|---|---|---|---|---|\n");
  for (const double thickness : {0.01, 0.005}) {
    SelfCollisionParams params{true, thickness};
    const testing::FoldingScene scene = testing::cloth_pile_scene(params);
    struct Start {
      const char* name;
      double scale;
      int free_steps;
    };
    for (const Start start :
         {Start{"as the tests", 1.0, 0}, Start{"1.6x as fast", 1.6, 0}, Start{"2x as fast", 2.0, 0},
          Start{"self-collision from step 10", 1.0, 10}}) {
      SimulationParams first = scene.params;
      first.self_collision.on = start.free_steps == 0;
      Simulation simulation(scene.network, scene.pins, first, start.scale * scene.initial_velocity);
      double most = 0.0;
      long crossed = 0;
      for (int step = 0; step < 460; ++step) {
        if (step == start.free_steps) {
          simulation.apply([&] {
            wobble::SimulationParams changed = simulation.params();
            changed.self_collision = params;
            return changed;
          }());
          crossed = testing::count_mesh_crossings(simulation.positions(), scene.network.F);
        }
        simulation.step();
        if (step >= 400) most = std::max(most, frame_energy(simulation).kinetic);
      }
      std::printf("| %.3g m | %s | %.3g J | %.0e J | %ld / %ld |\n", thickness, start.name, most,
                  thickness < 0.01 ? 1e-4 : 1e-5, crossed,
                  testing::count_mesh_crossings(simulation.positions(), scene.network.F));
      std::fflush(stdout);
    }
  }
}

}  // namespace wobble::benchmark

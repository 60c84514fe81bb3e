// wobble_busy_neighbour: every shipped scene's step time on a quiet machine and beside a busy
// process, measured in one run. Each scene runs in blocks of steps, quiet and busy in turn; for a
// busy block the program forks a child that spins on the processor (one process that never
// sleeps, like a build job or a busy browser tab) and kills it after the block. A slow spell of
// the machine hits both columns, so the ratio holds when absolute times drift.
//
//   wobble_busy_neighbour [--rounds N] [SCENE ...]     (default: every shipped scene)
//
// Prints one row a scene: vertices, springs, the first step after construction (the start-up
// hitch, if any), the median step quiet and busy, and busy / quiet. Never part of pass/fail.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "../io/shipped_scenes.h"
#include "io/load_scene.h"
#include "sim/parallel/worker_pool.h"
#include "sim/shapes/builtin_scenes.h"
#include "sim/simulation.h"

namespace {

// A child process that spins until killed.
pid_t start_busy_neighbour() {
  const pid_t child = fork();
  if (child == 0) {
    volatile unsigned long spin = 0;
    for (;;)
      spin = spin + 1;
  }
  // Let it get onto a processor before timing starts.
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  return child;
}

void stop_busy_neighbour(pid_t child) {
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double step_ms(wobble::Simulation& simulation) {
  const auto start = std::chrono::steady_clock::now();
  simulation.step();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

int main(int argc, char** argv) {
  int rounds = 4;
  std::vector<std::string> scenes;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--rounds" && i + 1 < argc) {
      rounds = std::max(1, std::atoi(argv[++i]));
    } else {
      scenes.push_back(argument);
    }
  }
  if (scenes.empty()) scenes = wobble::testing::shipped_scenes(WOBBLE_ASSETS_DIR);

  std::printf("worker pool: %d threads (%d usable processors)\n",
              wobble::WorkerPool::shared().threads(), wobble::usable_processors());
  std::printf("%d rounds of a quiet and a busy block per scene; times in ms per step\n\n", rounds);
  std::printf(
      "| scene | V | springs | iterations | first step | quiet median | busy median |"
      " busy / quiet |\n|---|---|---|---|---|---|---|---|\n");
  double worst = 0.0;
  for (const std::string& source : scenes) {
    const wobble::Scene scene = wobble::load_scene(source);
    wobble::Simulation simulation(scene.network, scene.pins, scene.params, scene.initial_velocity);
    const double first = step_ms(simulation);
    std::vector<double> warm;
    for (int i = 0; i < 5; ++i)
      warm.push_back(step_ms(simulation));
    // About a quarter of a second per block, at least 5 steps.
    const int steps = std::clamp(static_cast<int>(250.0 / std::max(median(warm), 1e-3)), 5, 400);
    std::vector<double> quiet, busy;
    for (int round = 0; round < rounds; ++round) {
      for (int i = 0; i < steps; ++i)
        quiet.push_back(step_ms(simulation));
      const pid_t neighbour = start_busy_neighbour();
      for (int i = 0; i < steps; ++i)
        busy.push_back(step_ms(simulation));
      stop_busy_neighbour(neighbour);
    }
    const double ratio = median(busy) / median(quiet);
    worst = std::max(worst, ratio);
    std::printf("| %s | %ld | %ld | %d | %.3f | %.3f | %.3f | %.2f |\n",
                std::filesystem::path(source).filename().string().c_str(),
                static_cast<long>(scene.network.V.rows()),
                static_cast<long>(scene.network.E.rows()), scene.params.iterations, first,
                median(quiet), median(busy), ratio);
    std::fflush(stdout);
  }
  std::printf("\nlargest busy / quiet: %.2f\n", worst);
  return 0;
}

#include "solver_race.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/load_scene.h"
#include "median.h"
#include "sim/instruments/stopwatch.h"
#include "sim/shapes/jelly_block.h"
#include "sim/simulation.h"

namespace wobble::benchmark {

namespace {

struct RaceScene {
  std::string name;
  SpringNetwork network;
  std::vector<int> pins;
  SimulationParams params;
  Eigen::MatrixXd velocity;
  int repeats = 5;
};

// The shipped curtain (assets/curtain.json: hanging from its top edge, pushed at 1.5 m/s) at
// another resolution and k, read as a user's scene file is.
RaceScene curtain(int resolution, double size, double k, int repeats) {
  const std::string json =
      "{\"name\": \"race\", \"mesh\": {\"generator\": \"cloth\", "
      "\"resolution\": " +
      std::to_string(resolution) + ", \"size\": " + std::to_string(size) +
      ", \"orientation\": \"vertical\", \"height\": 2.2}, "
      "\"pins\": \"top-edge\", \"material\": {\"k\": " +
      std::to_string(k) +
      ", \"density\": 0.3}, \"simulation\": {\"dt\": 0.016667, "
      "\"iterations\": 50}, \"initial_velocity\": [0.0, 0.0, 1.5]}";
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                     ("wobble-race-" + std::to_string(resolution) + ".json");
  std::ofstream(file) << json;
  const Scene loaded = load_scene(file.string());
  std::filesystem::remove(file);
  RaceScene scene;
  scene.name = "curtain " + std::to_string(resolution) + "x" + std::to_string(resolution) +
               " k=" + std::to_string(static_cast<long>(k));
  scene.network = loaded.network;
  scene.pins = loaded.pins;
  scene.params = loaded.params;
  scene.velocity = loaded.initial_velocity;
  scene.repeats = repeats;
  return scene;
}

RaceScene stiff_jelly() {
  JellyBlockOptions options;
  options.resolution = 8;
  options.size = 0.5;
  options.density = 100.0;
  RaceScene scene;
  scene.name = "stiff jelly 8^3 k=80000";
  scene.network = make_jelly_block(options);
  scene.network.V.col(1).array() += 1.0;
  scene.params.k = 8e4;
  scene.params.damping = 1.0;
  scene.params.iterations = 50;
  scene.velocity = Eigen::MatrixXd::Zero(scene.network.V.rows(), 3);
  // Spinning and falling: a push that bends it.
  for (Eigen::Index i = 0; i < scene.network.V.rows(); ++i) {
    scene.velocity(i, 0) = 2.0 * (scene.network.V(i, 1) - 1.25);
    scene.velocity(i, 1) = -1.5;
  }
  scene.repeats = 20;
  return scene;
}

struct Run {
  std::vector<double> energy;
  double milliseconds = 0.0;
};

// One step of `solver` with `iterations` from the scene's first state: its energy trace, and the
// median wall time of `repeats` untraced steps from the same state.
Run run_step(const RaceScene& scene, const std::string& solver, int iterations) {
  SimulationParams params = scene.params;
  params.solver = solver;
  params.iterations = iterations;
  Simulation simulation(scene.network, scene.pins, params, scene.velocity);
  const Eigen::MatrixXd current = simulation.positions();
  const Eigen::MatrixXd previous = current - params.dt * scene.velocity;
  simulation.set_convergence_recording(true);
  simulation.set_state(current, previous);
  simulation.step();
  Run run;
  run.energy = simulation.last_convergence().energy;
  simulation.set_convergence_recording(false);
  std::vector<double> times;
  for (int repeat = 0; repeat < scene.repeats; ++repeat) {
    simulation.set_state(current, previous);
    const Stopwatch stopwatch;
    simulation.step();
    times.push_back(stopwatch.milliseconds());
  }
  run.milliseconds = median(times);
  return run;
}

void race(const RaceScene& scene) {
  const int plain = 50;
  const Run local_global = run_step(scene, "local-global", plain);
  const double target = local_global.energy.back();
  // L-BFGS with room to spare, to find how many iterations reach the target.
  const Run traced = run_step(scene, "lbfgs", 200);
  int needed = -1;
  bool monotone = true;
  for (std::size_t i = 0; i < traced.energy.size(); ++i) {
    if (i > 0 && traced.energy[i] > traced.energy[i - 1]) monotone = false;
    if (needed < 0 && traced.energy[i] <= target) needed = static_cast<int>(i);
  }
  if (needed < 0) {
    std::printf(
        "solvers/%-26s local-global %2d it %8.2f ms  E %.9g | lbfgs never reached it "
        "in 200 (E %.9g)\n",
        scene.name.c_str(), plain, local_global.milliseconds, target, traced.energy.back());
    return;
  }
  const Run lbfgs = run_step(scene, "lbfgs", std::max(needed, 1));
  std::printf(
      "solvers/%-26s local-global %2d it %8.2f ms | lbfgs %3d it %8.2f ms | time ratio %.3f  "
      "(after 1 iteration E %.9g, after 50 local-global E %.9g, lbfgs's lowest %.9g; its "
      "energy %s)\n",
      scene.name.c_str(), plain, local_global.milliseconds, needed, lbfgs.milliseconds,
      lbfgs.milliseconds / local_global.milliseconds, local_global.energy[1], target,
      traced.energy.back(), monotone ? "never rose" : "ROSE");
}

}  // namespace

void print_solver_race() {
  std::printf(
      "\nL-BFGS against local-global: iterations and time to reach the energy of 50 "
      "local-global iterations, one step (median of repeats)\n");
  race(curtain(81, 2.0, 1e5, 9));
  race(stiff_jelly());
  race(curtain(256, 2.0, 1e5, 3));
}

}  // namespace wobble::benchmark

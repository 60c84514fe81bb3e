#include "volume_cost.h"

#include <cstdio>
#include <ctime>
#include <memory>
#include <vector>

#include "median.h"
#include "sim/parallel/worker_pool.h"
#include "sim/settings/setting_registry.h"
#include "sim/shapes/jelly_block.h"
#include "sim/simulation.h"

namespace wobble::benchmark {

namespace {

constexpr double volume_stiffness = 20000.0;  // Pa, as the shipped jellies

struct Block {
  SpringNetwork network;
  std::vector<int> pins;  // the base
  Eigen::MatrixXd push;   // m/s sideways, growing with height
};

Block make_block(int resolution) {
  JellyBlockOptions options;
  options.resolution = resolution;
  Block block{make_jelly_block(options), {}, {}};
  const int base = (resolution + 1) * (resolution + 1);
  for (int i = 0; i < base; ++i)
    block.pins.push_back(i);
  block.push = Eigen::MatrixXd::Zero(block.network.V.rows(), 3);
  block.push.col(0) = 2.0 * block.network.V.col(1);
  return block;
}

SimulationParams block_params(const char* solver, bool volume, int iterations = 50) {
  SimulationParams params;
  params.k = 1500.0;
  params.dt = 1.0 / 60.0;
  params.iterations = iterations;
  params.solver = solver;
  if (volume) {
    set_setting_value(params, "volume", 1.0);
    set_setting_value(params, "volume-stiffness", volume_stiffness);
  }
  return params;
}

struct Medians {
  double total = 0.0, local = 0.0, global = 0.0;  // ms a step
  double cpu = 0.0;  // the process's processor time a step (ms): its work, whatever the load
};

double process_cpu_ms() {
  timespec now;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return 1e3 * static_cast<double>(now.tv_sec) + 1e-6 * static_cast<double>(now.tv_nsec);
}

// The block without and with the term stepped in turn, one step each, so that a slow spell of the
// machine hits both; the medians of steps 11 to 10 + `steps`.
void paired_steps(const Block& block, const SimulationParams& off_params,
                  const SimulationParams& on_params, int steps, Medians& off, Medians& on,
                  long& off_nonzeros, long& on_nonzeros) {
  Simulation without(block.network, block.pins, off_params, block.push);
  Simulation with(block.network, block.pins, on_params, block.push);
  off_nonzeros = without.factor_nonzeros();
  on_nonzeros = with.factor_nonzeros();
  std::vector<double> times[2][4];
  for (int step = 0; step < 10 + steps; ++step) {
    Simulation* both[2] = {&without, &with};
    for (int side = 0; side < 2; ++side) {
      const double cpu_start = process_cpu_ms();
      both[side]->step();
      const double cpu = process_cpu_ms() - cpu_start;
      if (step < 10) continue;
      times[side][3].push_back(cpu);
      const StepTiming& timing = both[side]->last_step_timing();
      times[side][0].push_back(timing.total_ms);
      times[side][1].push_back(timing.local_ms);
      times[side][2].push_back(timing.global_ms);
    }
  }
  Medians* out[2] = {&off, &on};
  for (int side = 0; side < 2; ++side)
    *out[side] = {median(times[side][0]), median(times[side][1]), median(times[side][2]),
                  median(times[side][3])};
}

// How much of a step's motion `iterations` leave undone: from the state after a second of
// swaying, ‖p − p*‖ / ‖p* − pᵗ‖, p* the step solved with 400 plain iterations.
double remaining_error(const Block& block, const SimulationParams& params,
                       const Eigen::MatrixXd& current, const Eigen::MatrixXd& previous,
                       double* ms) {
  SimulationParams reference_params = params;
  reference_params.iterations = 400;
  reference_params.chebyshev = false;
  Simulation reference(block.network, block.pins, reference_params);
  reference.set_state(current, previous);
  reference.step();
  Simulation simulation(block.network, block.pins, params);
  std::vector<double> times;
  double error = 0.0;
  for (int repeat = 0; repeat < 5; ++repeat) {
    simulation.set_state(current, previous);
    simulation.step();
    times.push_back(simulation.last_step_timing().total_ms);
    // The first, whose rotations (if any) start where a fresh simulation's do, as the answer's.
    if (repeat == 0) {
      error = (simulation.positions() - reference.positions()).norm() /
              (reference.positions() - current).norm();
    }
  }
  *ms = median(times);
  return error;
}

}  // namespace

void print_volume_cost() {
  std::printf(
      "\nvolume term: median ms a step (steps in turn with and without), dt 16.7 ms, "
      "50 iterations, block with its base pinned, %d threads\n",
      WorkerPool::shared().threads());
  std::printf("%-5s %7s %-12s %19s %10s %10s %7s %23s %9s %21s %7s\n", "res", "tets", "solver",
              "nnz(L) off / on", "off (ms)", "on (ms)", "ratio", "local ms off / on", "real time",
              "cpu ms off / on", "ratio");
  for (const int resolution : {8, 11, 15}) {
    const Block block = make_block(resolution);
    const int steps = resolution <= 8 ? 40 : resolution <= 11 ? 20 : 10;
    for (const char* solver : {"local-global", "lbfgs"}) {
      Medians off, on;
      long off_nonzeros = 0, on_nonzeros = 0;
      paired_steps(block, block_params(solver, false), block_params(solver, true), steps, off, on,
                   off_nonzeros, on_nonzeros);
      std::printf(
          "%-5d %7ld %-12s %9ld / %7ld %10.2f %10.2f %6.2fx %11.2f / %9.2f %9s %9.2f / %9.2f "
          "%6.2fx\n",
          resolution, static_cast<long>(block.network.T.rows()), solver, off_nonzeros, on_nonzeros,
          off.total, on.total, on.total / off.total, off.local, on.local,
          on.total <= 1000.0 / 60.0 ? "yes" : "no", off.cpu, on.cpu, on.cpu / off.cpu);
    }
  }
}

void print_volume_iterations() {
  // The 20k-tetrahedron block: what fewer iterations, plain or with Chebyshev, cost and leave.
  const Block block = make_block(15);
  Simulation sway(block.network, block.pins, block_params("local-global", true), block.push);
  for (int step = 0; step < 60; ++step)
    sway.step();
  const Eigen::MatrixXd current = sway.positions(), previous = sway.previous_positions();
  std::printf(
      "\nresolution 15 (20,250 tetrahedra), local-global, one step from a second of "
      "swaying: median ms and the share of the step's motion left undone (400 plain "
      "iterations the answer)\n");
  std::printf("%-10s %-10s %12s %12s %14s %14s\n", "iterations", "chebyshev", "off (ms)", "on (ms)",
              "off undone", "on undone");
  for (const int iterations : {8, 10, 15, 20, 30, 50}) {
    for (const bool chebyshev : {false, true}) {
      double off_ms = 0.0, on_ms = 0.0;
      SimulationParams off_params = block_params("local-global", false, iterations);
      SimulationParams on_params = block_params("local-global", true, iterations);
      off_params.chebyshev = on_params.chebyshev = chebyshev;
      const double off_error = remaining_error(block, off_params, current, previous, &off_ms);
      const double on_error = remaining_error(block, on_params, current, previous, &on_ms);
      std::printf("%-10d %-10s %12.2f %12.2f %14.2e %14.2e\n", iterations, chebyshev ? "on" : "off",
                  off_ms, on_ms, off_error, on_error);
    }
  }
}

}  // namespace wobble::benchmark

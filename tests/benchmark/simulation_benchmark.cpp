// wobble_benchmark: Wobble's stepper against the plain reference, side by side in one process,
// then one table. Times on shared machines are noisy; the ratios are what to compare.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <string>

#include "benchmark_scenes.h"
#include "chebyshev_curve.h"
#include "contact_cost.h"
#include "instruments_cost.h"
#include "quantity_colors_cost.h"
#include "self_collision_cost.h"
#include "self_collision_motion.h"
#include "self_collision_settling.h"
#include "sim/simulation.h"
#include "solve_cost.h"
#include "solver_race.h"
#include "volume_cost.h"

namespace {

using wobble::Simulation;
using wobble::benchmark::BenchmarkScene;
using wobble::benchmark::ReferenceStepper;

// How many steps to time: enough for a stable mean, few enough that 256×256 stays quick.
int steps_for(const BenchmarkScene& scene) {
  const long n = scene.scene.network.V.rows();
  return n > 30000 ? 6 : n > 10000 ? 8 : n > 5000 ? 12 : 30;
}

Simulation& simulation_for(const BenchmarkScene& scene) {
  static std::map<std::string, std::unique_ptr<Simulation>> cache;
  std::unique_ptr<Simulation>& simulation = cache[scene.name];
  if (!simulation) {
    simulation =
        std::make_unique<Simulation>(scene.scene.network, scene.scene.pins, scene.scene.params);
  }
  return *simulation;
}

ReferenceStepper& reference_for(const BenchmarkScene& scene) {
  static std::map<std::string, std::unique_ptr<ReferenceStepper>> cache;
  std::unique_ptr<ReferenceStepper>& reference = cache[scene.name];
  if (!reference) reference = std::make_unique<ReferenceStepper>(scene.scene);
  return *reference;
}

double milliseconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// The plain reference and Wobble, one step each in turn, so that a slow spell of the machine
// hits both sides of the ratio; each side's best step is what the table compares.
void paired_step(benchmark::State& state, const BenchmarkScene* scene, int iterations) {
  Simulation& simulation = simulation_for(*scene);
  ReferenceStepper& reference = reference_for(*scene);
  simulation.apply(
      wobble::with_setting(simulation.params(), "iterations", static_cast<double>(iterations)));
  double plain = 1e300, wobble = 1e300, local = 0.0, global = 0.0;
  for (auto _ : state) {
    auto start = std::chrono::steady_clock::now();
    reference.step(iterations);
    plain = std::min(plain, milliseconds(start));
    start = std::chrono::steady_clock::now();
    simulation.step();
    wobble = std::min(wobble, milliseconds(start));
    local += simulation.last_step_timing().local_ms;
    global += simulation.last_step_timing().global_ms;
  }
  state.counters["plain_ms"] = plain;
  state.counters["wobble_ms"] = wobble;
  state.counters["local_ms"] = local / static_cast<double>(state.iterations());
  state.counters["global_ms"] = global / static_cast<double>(state.iterations());
  state.counters["factor_nonzeros"] = static_cast<double>(simulation.factor_nonzeros());
}

// The same for the precomputation: the reference's and Wobble's, in turn, best of each.
void paired_precompute(benchmark::State& state, const BenchmarkScene* scene) {
  double plain = 1e300, wobble = 1e300;
  for (auto _ : state) {
    auto start = std::chrono::steady_clock::now();
    {
      ReferenceStepper reference(scene->scene);
      benchmark::DoNotOptimize(reference.positions().data());
      plain = std::min(plain, milliseconds(start));
    }
    start = std::chrono::steady_clock::now();
    Simulation simulation(scene->scene.network, scene->scene.pins, scene->scene.params);
    benchmark::DoNotOptimize(simulation.factor_nonzeros());
    wobble = std::min(wobble, milliseconds(start));
  }
  state.counters["plain_ms"] = plain;
  state.counters["wobble_ms"] = wobble;
}

void wobble_refactor(benchmark::State& state, const BenchmarkScene* scene) {
  Simulation& simulation = simulation_for(*scene);
  double k = scene->scene.params.k;
  for (auto _ : state) {
    k = k == scene->scene.params.k ? 1.01 * k : scene->scene.params.k;
    simulation.apply(wobble::with_setting(simulation.params(), "k", k));
  }
  simulation.apply(wobble::with_setting(simulation.params(), "k", scene->scene.params.k));
}

// Keeps every run's time, by name, for the table printed at the end.
class TableReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      times[run.run_name.function_name] = run.GetAdjustedRealTime();
      for (const auto& [name, counter] : run.counters)
        counters[run.run_name.function_name + "/" + name] = counter.value;
    }
  }
  std::map<std::string, double> times, counters;
};

void print_table(const TableReporter& reporter) {
  const auto counter = [&](const std::string& name) {
    const auto found = reporter.counters.find(name);
    return found == reporter.counters.end() ? 0.0 : found->second;
  };
  const auto time = [&](const std::string& name) {
    const auto found = reporter.times.find(name);
    return found == reporter.times.end() ? 0.0 : found->second;
  };
  std::printf("\n(best of each side, plain and Wobble timed in turn; refactorization: mean)\n");
  std::printf("%-17s %7s %8s %9s | %-17s | %-6s | %-25s | %-25s | %s\n", "scene", "V", "springs",
              "nnz(L)", "precompute ms", "refac", "10 iterations ms/step", "50 iterations ms/step",
              "local/global (10 it)");
  std::printf("%-17s %7s %8s %9s | %7s %9s | %6s | %7s %7s %9s | %7s %7s %9s |\n", "", "", "", "",
              "plain", "wobble", "ms", "plain", "wobble", "speed-up", "plain", "wobble",
              "speed-up");
  for (const BenchmarkScene& scene : wobble::benchmark::benchmark_scenes()) {
    const std::string& s = scene.name;
    const std::string at10 = "paired_step/" + s + "/10/", at50 = "paired_step/" + s + "/50/";
    const double plain10 = counter(at10 + "plain_ms"), fast10 = counter(at10 + "wobble_ms");
    const double plain50 = counter(at50 + "plain_ms"), fast50 = counter(at50 + "wobble_ms");
    std::printf(
        "%-17s %7ld %8ld %9.0f | %7.1f %9.1f | %6.2f | %7.2f %7.2f %8.2fx | %7.2f %7.2f %8.2fx | "
        "%.2f / %.2f\n",
        s.c_str(), static_cast<long>(scene.scene.network.V.rows()),
        static_cast<long>(scene.scene.network.E.rows()), counter(at10 + "factor_nonzeros"),
        counter("paired_precompute/" + s + "/plain_ms"),
        counter("paired_precompute/" + s + "/wobble_ms"), time("wobble_refactor/" + s), plain10,
        fast10, plain10 / fast10, plain50, fast50, plain50 / fast50, counter(at10 + "local_ms"),
        counter(at10 + "global_ms"));
  }
}

// What reading a large factor in single precision costs in accuracy: 30 steps of 10 iterations
// from rest with the factor read as float and as double, the largest difference in any position
// as a share of the rest shape's bounding-box diagonal.
void print_single_precision_error() {
  for (const BenchmarkScene& scene : wobble::benchmark::benchmark_scenes()) {
    wobble::SimulationParams params = scene.scene.params;
    params.iterations = 10;
    Simulation automatic(scene.scene.network, scene.scene.pins, params);
    if (!automatic.solves_in_single_precision()) continue;
    params.single_precision_solve_above = std::numeric_limits<long>::max();
    Simulation exact(scene.scene.network, scene.scene.pins, params);
    for (int step = 0; step < 30; ++step) {
      automatic.step();
      exact.step();
    }
    const Eigen::MatrixXd& V = scene.scene.network.V;
    const double diagonal = (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm();
    const double difference = (automatic.positions() - exact.positions()).cwiseAbs().maxCoeff();
    std::printf(
        "\n%s: the factor is read in single precision; after 30 steps the positions "
        "differ from a double solve's by at most %.2g of the shape's size\n",
        scene.name.c_str(), difference / diagonal);
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  // Flags that print one part's rows alone instead of the timed benchmarks.
  struct Part {
    const char* flag;
    void (*print)();
  };
  static constexpr Part parts[] = {
      {"--contact", wobble::benchmark::print_contact_cost},
      {"--volume",
       [] {
         wobble::benchmark::print_volume_cost();
         wobble::benchmark::print_volume_iterations();
       }},
      {"--solvers", wobble::benchmark::print_solver_race},
      {"--self-collision-settling", wobble::benchmark::print_self_collision_settling},
      {"--self-collision-landing", wobble::benchmark::print_self_collision_landing},
      {"--self-collision-motion", wobble::benchmark::print_self_collision_motion},
      {"--self-collision",
       [] {
         wobble::benchmark::print_self_collision_motion();
         wobble::benchmark::print_self_collision_cost();
       }},
  };
  for (const Part& part : parts) {
    if (argc > 1 && std::string(argv[1]) == part.flag) {
      part.print();
      return 0;
    }
  }
  for (const BenchmarkScene& scene : wobble::benchmark::benchmark_scenes()) {
    const int steps = steps_for(scene);
    const int precomputes = std::max(3, steps / 3);
    benchmark::RegisterBenchmark(("paired_precompute/" + scene.name).c_str(), paired_precompute,
                                 &scene)
        ->Iterations(precomputes)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("wobble_refactor/" + scene.name).c_str(), wobble_refactor, &scene)
        ->Iterations(steps)
        ->Unit(benchmark::kMillisecond);
    for (const int iterations : {10, 50}) {
      const std::string name = "paired_step/" + scene.name + "/" + std::to_string(iterations);
      benchmark::RegisterBenchmark(name.c_str(), paired_step, &scene, iterations)
          ->Iterations(steps)
          ->Unit(benchmark::kMillisecond);
    }
  }
  TableReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  print_table(reporter);
  print_single_precision_error();
  wobble::benchmark::print_solve_cost();
  wobble::benchmark::print_chebyshev_curve(wobble::benchmark::benchmark_scenes().front());
  wobble::benchmark::print_contact_cost();
  wobble::benchmark::print_volume_cost();
  wobble::benchmark::print_self_collision_cost();
  wobble::benchmark::print_instruments_cost();
  wobble::benchmark::print_quantity_colors_cost();
  wobble::benchmark::print_solver_race();
  benchmark::Shutdown();
  return 0;
}

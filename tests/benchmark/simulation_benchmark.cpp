// wobble_benchmark: Wobble's stepper against the plain reference, side by side in one process,
// then one table. Times on shared machines are noisy; the ratios are what to compare.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <string>

#include "benchmark_scenes.h"
#include "chebyshev_curve.h"
#include "sim/simulation.h"

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

void wobble_step(benchmark::State& state, const BenchmarkScene* scene, int iterations) {
  Simulation& simulation = simulation_for(*scene);
  simulation.set_iterations(iterations);
  double local = 0.0, global = 0.0;
  for (auto _ : state) {
    simulation.step();
    local += simulation.last_step_timing().local_ms;
    global += simulation.last_step_timing().global_ms;
  }
  state.counters["local_ms"] = local / static_cast<double>(state.iterations());
  state.counters["global_ms"] = global / static_cast<double>(state.iterations());
  state.counters["factor_nonzeros"] = static_cast<double>(simulation.factor_nonzeros());
}

void reference_step(benchmark::State& state, const BenchmarkScene* scene, int iterations) {
  ReferenceStepper& reference = reference_for(*scene);
  for (auto _ : state)
    reference.step(iterations);
}

void wobble_precompute(benchmark::State& state, const BenchmarkScene* scene) {
  for (auto _ : state) {
    Simulation simulation(scene->scene.network, scene->scene.pins, scene->scene.params);
    benchmark::DoNotOptimize(simulation.factor_nonzeros());
  }
}

void reference_precompute(benchmark::State& state, const BenchmarkScene* scene) {
  for (auto _ : state) {
    ReferenceStepper reference(scene->scene);
    benchmark::DoNotOptimize(reference.positions().data());
  }
}

void wobble_refactor(benchmark::State& state, const BenchmarkScene* scene) {
  Simulation& simulation = simulation_for(*scene);
  double k = scene->scene.params.k;
  for (auto _ : state) {
    k = k == scene->scene.params.k ? 1.01 * k : scene->scene.params.k;
    simulation.set_k(k);
  }
  simulation.set_k(scene->scene.params.k);
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
  const auto time = [&](const std::string& name) {
    const auto found = reporter.times.find(name);
    return found == reporter.times.end() ? 0.0 : found->second;
  };
  std::printf("\n%-17s %7s %8s %9s | %-17s | %-6s | %-25s | %-25s | %s\n", "scene", "V", "springs",
              "nnz(L)", "precompute ms", "refac", "10 iterations ms/step", "50 iterations ms/step",
              "local/global (10 it)");
  std::printf("%-17s %7s %8s %9s | %7s %9s | %6s | %7s %7s %9s | %7s %7s %9s |\n", "", "", "", "",
              "plain", "wobble", "ms", "plain", "wobble", "speed-up", "plain", "wobble",
              "speed-up");
  for (const BenchmarkScene& scene : wobble::benchmark::benchmark_scenes()) {
    const std::string& s = scene.name;
    const double plain10 = time("reference_step/" + s + "/10"),
                 fast10 = time("wobble_step/" + s + "/10");
    const double plain50 = time("reference_step/" + s + "/50"),
                 fast50 = time("wobble_step/" + s + "/50");
    const std::string counters = "wobble_step/" + s + "/10/";
    std::printf(
        "%-17s %7ld %8ld %9.0f | %7.1f %9.1f | %6.2f | %7.2f %7.2f %8.2fx | %7.2f %7.2f %8.2fx | "
        "%.2f / %.2f\n",
        s.c_str(), static_cast<long>(scene.scene.network.V.rows()),
        static_cast<long>(scene.scene.network.E.rows()),
        reporter.counters.count(counters + "factor_nonzeros")
            ? reporter.counters.at(counters + "factor_nonzeros")
            : 0.0,
        time("reference_precompute/" + s), time("wobble_precompute/" + s),
        time("wobble_refactor/" + s), plain10, fast10, plain10 / fast10, plain50, fast50,
        plain50 / fast50,
        reporter.counters.count(counters + "local_ms") ? reporter.counters.at(counters + "local_ms")
                                                       : 0.0,
        reporter.counters.count(counters + "global_ms")
            ? reporter.counters.at(counters + "global_ms")
            : 0.0);
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
  for (const BenchmarkScene& scene : wobble::benchmark::benchmark_scenes()) {
    const int steps = steps_for(scene);
    const int precomputes = std::max(1, steps / 3);
    benchmark::RegisterBenchmark(("reference_precompute/" + scene.name).c_str(),
                                 reference_precompute, &scene)
        ->Iterations(precomputes)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("wobble_precompute/" + scene.name).c_str(), wobble_precompute,
                                 &scene)
        ->Iterations(precomputes)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("wobble_refactor/" + scene.name).c_str(), wobble_refactor, &scene)
        ->Iterations(steps)
        ->Unit(benchmark::kMillisecond);
    for (const int iterations : {10, 50}) {
      const std::string suffix = "/" + scene.name + "/" + std::to_string(iterations);
      // Interleaved, so that a slow spell of the machine hits both sides of each ratio.
      benchmark::RegisterBenchmark(("reference_step" + suffix).c_str(), reference_step, &scene,
                                   iterations)
          ->Iterations(steps)
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("wobble_step" + suffix).c_str(), wobble_step, &scene,
                                   iterations)
          ->Iterations(steps)
          ->Unit(benchmark::kMillisecond);
    }
  }
  TableReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  print_table(reporter);
  print_single_precision_error();
  wobble::benchmark::print_chebyshev_curve(wobble::benchmark::benchmark_scenes().front());
  benchmark::Shutdown();
  return 0;
}

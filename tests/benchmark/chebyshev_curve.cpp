#include "chebyshev_curve.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "sim/simulation.h"

namespace wobble::benchmark {

namespace {

struct Point {
  double milliseconds;
  double error;  // relative to the converged step, ‖q_k − q*‖ / ‖q_0 − q*‖
};

// One step of `iterations` from the saved state, timed (best of 3) and measured against q*.
Point measure(Simulation& simulation, const Eigen::MatrixXd& current,
              const Eigen::MatrixXd& previous, const Eigen::MatrixXd& converged, int iterations) {
  simulation.set_iterations(iterations);
  double best = 1e300;
  for (int repeat = 0; repeat < 3; ++repeat) {
    simulation.set_state(current, previous);
    const auto start = std::chrono::steady_clock::now();
    simulation.step();
    best = std::min(
        best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                  .count());
  }
  const double error = (simulation.positions() - converged).norm() / (current - converged).norm();
  simulation.set_state(current, previous);
  return {best, error};
}

}  // namespace

void print_chebyshev_curve(const BenchmarkScene& scene) {
  Simulation simulation(scene.scene.network, scene.scene.pins, scene.scene.params);
  // Let the cloth fall for a while, so the step being measured has motion in it.
  simulation.set_iterations(10);
  for (int frame = 0; frame < 30; ++frame)
    simulation.step();
  const Eigen::MatrixXd current = simulation.positions();
  const Eigen::MatrixXd previous = simulation.previous_positions();
  simulation.set_iterations(500);
  simulation.step();
  const Eigen::MatrixXd converged = simulation.positions();
  simulation.set_state(current, previous);

  const std::vector<int> counts = {1, 2, 3, 4, 5, 6, 8, 10, 15, 20, 30, 50};
  std::vector<Point> plain, chebyshev;
  for (int iterations : counts)
    plain.push_back(measure(simulation, current, previous, converged, iterations));
  simulation.set_chebyshev(true);  // estimates ρ here, from this state
  for (int iterations : counts)
    chebyshev.push_back(measure(simulation, current, previous, converged, iterations));

  std::printf("\nerror against the converged step (500 iterations), %s, rho = %.4f\n",
              scene.name.c_str(), simulation.chebyshev_spectral_radius());
  std::printf("%10s | %10s %10s | %10s %10s\n", "iterations", "plain ms", "error", "chebyshev",
              "error");
  double plain10 = 0.0, plain10_ms = 0.0;
  for (std::size_t i = 0; i < counts.size(); ++i) {
    std::printf("%10d | %10.2f %10.4f | %10.2f %10.4f\n", counts[i], plain[i].milliseconds,
                plain[i].error, chebyshev[i].milliseconds, chebyshev[i].error);
    if (counts[i] == 10) {
      plain10 = plain[i].error;
      plain10_ms = plain[i].milliseconds;
    }
  }
  for (std::size_t i = 0; i < counts.size(); ++i) {
    if (chebyshev[i].error <= plain10) {
      std::printf(
          "chebyshev reaches the error of 10 plain iterations (%.4f) after %d: %.2f ms "
          "against %.2f ms, %.2f of the time\n",
          plain10, counts[i], chebyshev[i].milliseconds, plain10_ms,
          chebyshev[i].milliseconds / plain10_ms);
      return;
    }
  }
  std::printf("chebyshev does not reach the error of 10 plain iterations (%.4f)\n", plain10);
}

}  // namespace wobble::benchmark

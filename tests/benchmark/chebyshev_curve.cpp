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
  double error;  // relative to the converged step, ‖q_k − q*‖ / ‖pᵗ − q*‖
};

// One step of `iterations` from the given state, timed (best of 3) and measured against q*.
// Leaves the simulation in that state.
Point measure(Simulation& simulation, const Eigen::MatrixXd& current,
              const Eigen::MatrixXd& previous, const Eigen::MatrixXd& converged, int iterations) {
  simulation.apply(
      wobble::with_setting(simulation.params(), "iterations", static_cast<double>(iterations)));
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

// The positions one step of `iterations` from `simulation`'s state gives; the state and the
// iteration count are left as they were.
Eigen::MatrixXd step_from_here(Simulation& simulation, int iterations) {
  const Eigen::MatrixXd current = simulation.positions();
  const Eigen::MatrixXd previous = simulation.previous_positions();
  const int kept = simulation.params().iterations;
  simulation.apply(
      wobble::with_setting(simulation.params(), "iterations", static_cast<double>(iterations)));
  simulation.step();
  Eigen::MatrixXd next = simulation.positions();
  simulation.set_state(current, previous);
  simulation.apply(
      wobble::with_setting(simulation.params(), "iterations", static_cast<double>(kept)));
  return next;
}

// The step from `simulation`'s state, converged by `iterations` plain iterations.
Eigen::MatrixXd converged_step(Simulation& simulation, int iterations) {
  const bool accelerated = simulation.params().chebyshev;
  simulation.apply(wobble::with_setting(simulation.params(), "chebyshev", false));
  Eigen::MatrixXd converged = step_from_here(simulation, iterations);
  simulation.apply(wobble::with_setting(simulation.params(), "chebyshev", accelerated));
  return converged;
}

// The error of one step of `iterations` from the simulation's state, against `converged` and
// relative to ‖pᵗ − q*‖.
double step_error(Simulation& simulation, const Eigen::MatrixXd& converged, int iterations) {
  return (step_from_here(simulation, iterations) - converged).norm() /
         (simulation.positions() - converged).norm();
}

// Over a fall of 120 frames (10 plain iterations a step), at every 10th step: how many
// accelerated iterations reach the error of 10 plain ones, both from the inertial prediction.
void print_fall_summary(const BenchmarkScene& scene) {
  Simulation simulation(scene.scene.network, scene.scene.pins, scene.scene.params);
  simulation.apply(wobble::with_setting(simulation.params(), "iterations", 10.0));
  std::vector<int> needed;
  for (int frame = 1; frame <= 120; ++frame) {
    simulation.step();
    if (frame % 10 != 0) continue;
    const Eigen::MatrixXd converged = converged_step(simulation, 400);
    const double plain = step_error(simulation, converged, 10);
    simulation.apply(
        wobble::with_setting(simulation.params(), "chebyshev",
                             true));  // ρ from the first sample's state, as a user would get it
    int n = 1;
    while (n < 10 && step_error(simulation, converged, n) > plain)
      ++n;
    simulation.apply(wobble::with_setting(simulation.params(), "chebyshev", false));
    needed.push_back(n);
  }
  std::printf(
      "over a 120-frame fall (rho = %.4f, estimated at step 10), chebyshev iterations "
      "that reach the error of 10 plain ones, every 10th step:",
      simulation.chebyshev_spectral_radius());
  double sum = 0.0;
  for (int n : needed) {
    std::printf(" %d", n);
    sum += n;
  }
  std::printf(" (mean %.1f)\n", sum / static_cast<double>(needed.size()));
}

}  // namespace

void print_chebyshev_curve(const BenchmarkScene& scene) {
  // Plain iterations from pᵗ (the course's start), plain and accelerated ones from the inertial
  // prediction (Wobble's), all measured against the same converged step.
  SimulationParams from_current = scene.scene.params;
  from_current.first_iterate = FirstIterate::current_positions;
  SimulationParams from_inertia = scene.scene.params;
  from_inertia.first_iterate = FirstIterate::inertial_prediction;
  Simulation course(scene.scene.network, scene.scene.pins, from_current);
  Simulation simulation(scene.scene.network, scene.scene.pins, from_inertia);
  // Let the cloth fall for a while, so the step being measured has motion in it.
  simulation.apply(wobble::with_setting(simulation.params(), "iterations", 10.0));
  for (int frame = 0; frame < 30; ++frame)
    simulation.step();
  const Eigen::MatrixXd current = simulation.positions();
  const Eigen::MatrixXd previous = simulation.previous_positions();
  const Eigen::MatrixXd converged = converged_step(simulation, 500);

  const std::vector<int> counts = {1, 2, 3, 4, 5, 6, 8, 10, 15, 20, 30, 50};
  std::vector<Point> plain_course, plain, chebyshev;
  for (int iterations : counts) {
    plain_course.push_back(measure(course, current, previous, converged, iterations));
    plain.push_back(measure(simulation, current, previous, converged, iterations));
  }
  simulation.apply(wobble::with_setting(simulation.params(), "chebyshev",
                                        true));  // estimates ρ here, from this state
  for (int iterations : counts)
    chebyshev.push_back(measure(simulation, current, previous, converged, iterations));

  std::printf(
      "\nerror against the converged step (500 iterations), %s, after 30 frames, rho = %.4f\n",
      scene.name.c_str(), simulation.chebyshev_spectral_radius());
  std::printf("%10s | %21s | %21s | %21s\n", "", "plain, from p^t", "plain, from 2p^t-p^t-1",
              "chebyshev, same start");
  std::printf("%10s | %10s %10s | %10s %10s | %10s %10s\n", "iterations", "ms", "error", "ms",
              "error", "ms", "error");
  double plain10 = 0.0, plain10_ms = 0.0;
  for (std::size_t i = 0; i < counts.size(); ++i) {
    std::printf("%10d | %10.2f %10.4f | %10.2f %10.4f | %10.2f %10.4f\n", counts[i],
                plain_course[i].milliseconds, plain_course[i].error, plain[i].milliseconds,
                plain[i].error, chebyshev[i].milliseconds, chebyshev[i].error);
    if (counts[i] == 10) {
      plain10 = plain[i].error;
      plain10_ms = plain[i].milliseconds;
    }
  }
  bool reached = false;
  for (std::size_t i = 0; i < counts.size() && !reached; ++i) {
    if (chebyshev[i].error <= plain10) {
      std::printf(
          "chebyshev reaches the error of 10 plain iterations from the same start (%.4f) after "
          "%d: %.2f ms against %.2f ms, %.2f of the time\n",
          plain10, counts[i], chebyshev[i].milliseconds, plain10_ms,
          chebyshev[i].milliseconds / plain10_ms);
      reached = true;
    }
  }
  if (!reached) {
    std::printf("chebyshev does not reach the error of 10 plain iterations (%.4f)\n", plain10);
  }
  print_fall_summary(scene);
}

}  // namespace wobble::benchmark

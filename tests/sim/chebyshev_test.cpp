#include "sim/solver/chebyshev.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/shapes/builtin_scenes.h"
#include "sim/simulation.h"

namespace {

TEST(Chebyshev, SpectralRadiusIsTheSettledRatioOfUpdates) {
  std::vector<double> norms;
  for (int k = 0; k < 20; ++k)
    norms.push_back((k < 5 ? 3.0 : 1.0) * std::pow(0.8, k));  // an early transient, then 0.8
  EXPECT_NEAR(wobble::ChebyshevAcceleration::estimate_spectral_radius(norms), 0.8, 1e-12);
  EXPECT_EQ(wobble::ChebyshevAcceleration::estimate_spectral_radius({}), 0.0);
  EXPECT_EQ(wobble::ChebyshevAcceleration::estimate_spectral_radius({1.0, 2.0, 4.0}), 0.999);
}

// One step of `iterations` from the cloth's state after 20 frames; returns the error against
// the converged step (3000 plain iterations: 400 left plain runs visibly short of it), relative
// to ‖pᵗ − q*‖.
double step_error(bool chebyshev, int iterations,
                  wobble::FirstIterate first = wobble::FirstIterate::inertial_prediction) {
  wobble::Scene scene = wobble::make_builtin_scene("cloth");
  scene.params.first_iterate = first;
  wobble::Simulation simulation(scene.network, scene.pins, scene.params);
  simulation.apply(wobble::with_setting(simulation.params(), "iterations", 10.0));
  for (int frame = 0; frame < 20; ++frame)
    simulation.step();
  const Eigen::MatrixXd current = simulation.positions(),
                        previous = simulation.previous_positions();
  simulation.apply(wobble::with_setting(simulation.params(), "iterations", 3000.0));
  simulation.step();
  const Eigen::MatrixXd converged = simulation.positions();
  simulation.set_state(current, previous);
  simulation.apply(wobble::with_setting(simulation.params(), "chebyshev", chebyshev));
  simulation.apply(
      wobble::with_setting(simulation.params(), "iterations", static_cast<double>(iterations)));
  simulation.step();
  return (simulation.positions() - converged).norm() / (current - converged).norm();
}

TEST(Chebyshev, SixAcceleratedIterationsBeatTenPlainOnes) {
  // Both start from the inertial prediction, which leaves little for the first iterations to do.
  // Here 6 accelerated iterations leave 0.048 of the error and 10 plain ones 0.068: a margin
  // that a broken recurrence or a wrong ρ loses.
  const double plain = step_error(false, 10);
  const double accelerated = step_error(true, 6);
  std::cout << "  error after 10 plain iterations " << plain << ", after 6 accelerated "
            << accelerated << "\n";
  EXPECT_LT(accelerated, plain);
}

TEST(FirstIterate, TheInertialPredictionStartsCloserAndEndsAtTheSameStep) {
  // The state after 20 frames differs with the start (fewer iterations settle differently), so
  // each is measured against its own converged step.
  using wobble::FirstIterate;
  const double from_current = step_error(false, 10, FirstIterate::current_positions);
  const double from_inertia = step_error(false, 10, FirstIterate::inertial_prediction);
  std::cout << "  error after 10 plain iterations: from p^t " << from_current
            << ", from the inertial prediction " << from_inertia << "\n";
  EXPECT_LT(from_inertia, 0.5 * from_current);
  // This soft cloth converges slowly either way (0.028 left from p^t after 1500 iterations).
  EXPECT_LT(step_error(false, 1500, FirstIterate::current_positions), 0.05);
  EXPECT_LT(step_error(false, 1500, FirstIterate::inertial_prediction), 0.05);
}

TEST(Chebyshev, ConvergesToTheSameStep) {
  // Acceleration changes how fast the iterations get there, not where they go: with enough
  // iterations both approach the converged step, the accelerated ones faster.
  const double plain = step_error(false, 200), accelerated = step_error(true, 200);
  std::cout << "  error after 200 iterations: plain " << plain << ", accelerated " << accelerated
            << "\n";
  // This soft cloth converges slowly (200 plain iterations leave 3% of the error): the accelerated
  // run must be clearly closer, and close.
  EXPECT_LT(accelerated, 0.6 * plain);
  EXPECT_LT(accelerated, 0.02);
}

TEST(Chebyshev, EstimatesRhoOnceWhenTurnedOn) {
  const wobble::Scene scene = wobble::make_builtin_scene("cloth");
  wobble::Simulation simulation(scene.network, scene.pins, scene.params);
  EXPECT_EQ(simulation.chebyshev_spectral_radius(), 0.0);
  const Eigen::MatrixXd before = simulation.positions();
  simulation.apply(wobble::with_setting(simulation.params(), "chebyshev", true));
  EXPECT_GT(simulation.chebyshev_spectral_radius(), 0.5);
  EXPECT_LT(simulation.chebyshev_spectral_radius(), 1.0);
  EXPECT_EQ(simulation.positions(), before) << "calibration must not move the cloth";
  EXPECT_TRUE(simulation.params().chebyshev);
}

TEST(Chebyshev, StaysStableWithFewIterationsThroughADrag) {
  // What `--drag 0:0.5,0.5,0.5@10-20` does to the built-in cloth: vertex 0 held and pulled half a
  // metre along each axis over ten frames, then let go. A bolder variant of the acceleration
  // (Chebyshev polynomials on [0, ρ] with the first step stretched) threw this cloth away within
  // a few frames of the drag at 1 and 3 iterations.
  const wobble::Scene scene = wobble::make_builtin_scene("cloth");
  for (int iterations = 1; iterations <= 5; ++iterations) {
    SCOPED_TRACE(iterations);
    wobble::Simulation simulation(scene.network, scene.pins, scene.params);
    simulation.apply(wobble::with_setting(simulation.params(), "chebyshev", true));
    simulation.apply(
        wobble::with_setting(simulation.params(), "iterations", static_cast<double>(iterations)));
    const bool was_pinned = simulation.is_pinned(0);
    for (int frame = 0; frame < 150; ++frame) {
      if (frame == 10 && !was_pinned) simulation.pin(0);
      if (frame >= 10 && frame <= 20) {
        const Eigen::Vector3d start = scene.network.V.row(0).transpose();
        const double share = (frame - 9) / 11.0;
        simulation.set_pin_target(0, start + share * Eigen::Vector3d(0.5, 0.5, 0.5));
      }
      if (frame == 21 && !was_pinned) simulation.unpin(0);
      ASSERT_EQ(simulation.step(), wobble::StepStatus::ok) << "frame " << frame;
    }
    EXPECT_TRUE(simulation.positions().allFinite());
  }
}

}  // namespace

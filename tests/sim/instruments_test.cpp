// The classroom instruments of sim/instruments: the step objective and its gradient, the
// convergence trace a step records, and the frame energy.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/instruments/convergence_trace.h"
#include "sim/instruments/frame_energy.h"
#include "sim/instruments/step_objective.h"
#include "sim/shapes/builtin_scenes.h"
#include "sim/simulation.h"
#include "test_meshes.h"

namespace wobble {
namespace {

using testing::all_test_meshes;
using testing::grid_mesh;
using testing::test_params;

TEST(StepObjective, GradientMatchesCentralDifferences) {
  const testing::TestMesh mesh = grid_mesh();
  const Eigen::Index n = mesh.network.V.rows();
  Eigen::VectorXd r(mesh.network.E.rows());
  for (Eigen::Index e = 0; e < r.size(); ++e) {
    r(e) = (mesh.network.V.row(mesh.network.E(e, 0)) - mesh.network.V.row(mesh.network.E(e, 1)))
               .norm();
  }
  std::srand(7);
  const Eigen::MatrixXd current = mesh.network.V + 0.01 * Eigen::MatrixXd::Random(n, 3);
  const Eigen::MatrixXd previous = current + 0.005 * Eigen::MatrixXd::Random(n, 3);
  const Eigen::MatrixXd fext = testing::gravity_forces(mesh.network.m);
  const StepObjectiveTerms terms{
      mesh.network.E, r, mesh.network.m, 300.0, 1.0 / 60.0, 2.0, current, previous, fext};
  const Eigen::MatrixXd p = current + 0.02 * Eigen::MatrixXd::Random(n, 3);
  Eigen::MatrixXd gradient;
  const double energy = step_objective(terms, p, &gradient);
  EXPECT_NEAR(energy, step_objective(terms, p), 1e-14 * std::abs(energy));
  const double h = 1e-6;
  for (Eigen::Index i = 0; i < n; i += 5) {
    for (int c = 0; c < 3; ++c) {
      Eigen::MatrixXd plus = p, minus = p;
      plus(i, c) += h;
      minus(i, c) -= h;
      const double difference =
          (step_objective(terms, plus) - step_objective(terms, minus)) / (2.0 * h);
      // Central differences of a smooth function: error O(h²) plus rounding of about 1e-16/h.
      EXPECT_NEAR(gradient(i, c), difference, 1e-6 * (1.0 + std::abs(difference)))
          << "vertex " << i << " coordinate " << c;
    }
  }
  // The vertex terms are the objective without the springs.
  double springs = 0.0;
  for (Eigen::Index e = 0; e < r.size(); ++e) {
    const double stretch =
        (p.row(mesh.network.E(e, 0)) - p.row(mesh.network.E(e, 1))).norm() - r(e);
    springs += stretch * stretch;
  }
  EXPECT_NEAR(step_objective_vertex_terms(terms, p) + 150.0 * springs, energy,
              1e-12 * std::abs(energy));
}

// What the simulation recorded, against the objective and gradient evaluated directly at the
// iterates an observer sees.
void expect_trace_matches_direct_evaluation(bool chebyshev, double damping) {
  for (const auto& mesh : all_test_meshes()) {
    SCOPED_TRACE(mesh.name + (chebyshev ? " chebyshev" : " plain"));
    SimulationParams params = test_params();
    params.chebyshev = chebyshev;
    params.damping = damping;
    Simulation simulation(mesh.network, mesh.pins, params);
    simulation.set_convergence_recording(true);
    for (int step = 0; step < 5; ++step)
      simulation.step();
    std::vector<double> energies, gradients;
    Eigen::MatrixXd gradient;
    simulation.set_iteration_observer([&](int, const Eigen::MatrixXd& p) {
      energies.push_back(simulation.step_energy(p, &gradient));
      gradients.push_back(gradient.norm());
    });
    simulation.step();
    const ConvergenceTrace& trace = simulation.last_convergence();
    ASSERT_EQ(trace.iterations(), params.iterations);
    EXPECT_EQ(trace.chebyshev, chebyshev);
    // The observer sees each solve's output: trace entries 1 to 50.
    for (int i = 1; i <= params.iterations; ++i) {
      EXPECT_NEAR(trace.energy[i], energies[i - 1], 1e-11 * std::abs(energies[i - 1]) + 1e-12)
          << "iteration " << i;
      // The pins' term w(p − target), w = 1e10, is computed from positions of about 1 m: its
      // rounding is about 1e10 · 1e-16 = 1e-6 N whichever way the gradient is formed.
      EXPECT_NEAR(trace.gradient_norm[i], gradients[i - 1], 1e-6 * gradients[i - 1] + 1e-5)
          << "iteration " << i;
    }
  }
}

TEST(ConvergenceTrace, MatchesTheObjectiveAtEachIterate) {
  expect_trace_matches_direct_evaluation(/*chebyshev=*/false, 0.0);
  expect_trace_matches_direct_evaluation(/*chebyshev=*/false, 3.0);
}

TEST(ConvergenceTrace, MatchesTheObjectiveAtEachChebyshevIterate) {
  expect_trace_matches_direct_evaluation(/*chebyshev=*/true, 0.0);
}

TEST(ConvergenceTrace, EnergyNeverRisesOverPlainIterations) {
  for (const std::string& name : builtin_scene_names()) {
    SCOPED_TRACE(name);
    Scene scene = make_builtin_scene(name);
    scene.params.chebyshev = false;  // the guarantee is the plain iteration's
    Simulation simulation(scene.network, scene.pins, scene.params, scene.initial_velocity);
    simulation.set_convergence_recording(true);
    for (int step = 0; step < 30; ++step) {
      ASSERT_EQ(simulation.step(), StepStatus::ok);
      const ConvergenceTrace& trace = simulation.last_convergence();
      for (int i = 1; i <= trace.iterations(); ++i) {
        // Each half-step minimizes exactly; 1e-12 relative is the rounding of summing the terms.
        ASSERT_LE(trace.energy[i], trace.energy[i - 1] + 1e-12 * std::abs(trace.energy[i - 1]))
            << "step " << step + 1 << " iteration " << i;
      }
    }
  }
}

TEST(ConvergenceTrace, RecordingOffRecordsNothingAndStepsAlike) {
  const testing::TestMesh mesh = grid_mesh();
  Simulation quiet(mesh.network, mesh.pins, test_params());
  Simulation recorded(mesh.network, mesh.pins, test_params());
  recorded.set_convergence_recording(true);
  for (int step = 0; step < 10; ++step) {
    quiet.step();
    recorded.step();
  }
  EXPECT_TRUE(quiet.last_convergence().energy.empty());
  EXPECT_EQ(quiet.last_step_timing().instruments_ms, 0.0);
  EXPECT_EQ(recorded.last_convergence().iterations(), 50);
  // Recording only reads: the positions are the same to the last bit.
  EXPECT_EQ((quiet.positions() - recorded.positions()).cwiseAbs().maxCoeff(), 0.0);
}

TEST(ConvergenceTrace, StiffClothIsFarFromConvergedAndSoftChainConverges) {
  Scene cloth = make_builtin_scene("cloth");
  cloth.params.k = 1e6;  // the example: 50 iterations leave it nearly where it was
  Simulation stiff(cloth.network, cloth.pins, cloth.params);
  stiff.set_convergence_recording(true);
  for (int step = 0; step < 20; ++step)
    stiff.step();
  EXPECT_EQ(classify(stiff.last_convergence()), Convergence::far)
      << stiff.last_convergence().gradient_reduction();
  stiff.apply(wobble::with_setting(stiff.params(), "iterations",
                                   static_cast<double>(Simulation::max_iterations)));
  stiff.step();
  EXPECT_LT(stiff.last_convergence().gradient_reduction(), 0.5)
      << "more iterations must get further";

  const testing::TestMesh chain = testing::chain_mesh(4);
  Simulation soft(chain.network, chain.pins, test_params());
  soft.set_convergence_recording(true);
  for (int step = 0; step < 20; ++step)
    soft.step();
  EXPECT_EQ(classify(soft.last_convergence()), Convergence::converged)
      << soft.last_convergence().gradient_reduction();
}

TEST(ConvergenceTrace, ClassifiesByTheGradientsReduction) {
  ConvergenceTrace trace;
  trace.gradient_norm = {1.0, 4.0, 2.0, 3e-3};  // the start is the larger of the first two
  EXPECT_DOUBLE_EQ(trace.gradient_reduction(), 3e-3 / 4.0);
  EXPECT_EQ(classify(trace), Convergence::converged);
  trace.gradient_norm.back() = 0.2;
  EXPECT_EQ(classify(trace), Convergence::partial);
  trace.gradient_norm.back() = 1.0;
  EXPECT_EQ(classify(trace), Convergence::far);
}

// A step that barely moves is measured against the scale of the step's inertia, not against its
// own tiny start: the default cloth hanging at rest reads partly converged (amber), as it did
// while it swung, where before its light went red (0.13 at step 791, 0.67 at step 1544) while
// nothing was wrong; a leftover near that scale still reads far.
TEST(ConvergenceTrace, AClothAtRestIsNotReadAsFarFromConverged) {
  const Scene scene = make_builtin_scene("cloth");
  Simulation cloth(scene.network, scene.pins, scene.params);
  for (int step = 0; step < 780; ++step)
    cloth.step();
  cloth.set_convergence_recording(true);
  for (int step = 0; step < 20; ++step) {
    cloth.step();
    const ConvergenceTrace& trace = cloth.last_convergence();
    ASSERT_GT(trace.force_scale, 0.0);
    EXPECT_LT(trace.gradient_norm[0], 0.5 * trace.force_scale) << "the step barely moves";
    EXPECT_NE(classify(trace), Convergence::far) << trace.gradient_reduction();
  }

  ConvergenceTrace trace;
  trace.gradient_norm = {0.01, 0.02, 0.015};
  EXPECT_GT(trace.gradient_reduction(), 0.5) << "without a scale, against its own start";
  trace.force_scale = 1.0;
  EXPECT_DOUBLE_EQ(trace.gradient_reduction(), 0.015);
  trace.gradient_norm.back() = 0.5;
  EXPECT_EQ(classify(trace), Convergence::far);
}

TEST(FrameEnergy, FreeFallingVertex) {
  SpringNetwork network;
  network.V = Eigen::MatrixXd(2, 3);
  network.V << 0.0, 2.0, 0.0, 0.3, 2.0, 0.0;
  network.E = Eigen::MatrixXi(1, 2);
  network.E << 0, 1;
  network.m = Eigen::Vector2d(0.5, 1.5);
  SimulationParams params = test_params();
  Simulation simulation(network, {}, params);
  const FrameEnergy start = frame_energy(simulation);
  EXPECT_DOUBLE_EQ(start.kinetic, 0.0);
  EXPECT_DOUBLE_EQ(start.spring, 0.0);
  EXPECT_NEAR(start.gravity, 2.0 * 9.81 * 2.0, 1e-12);  // Σ m g y from y = 0
  for (int step = 0; step < 10; ++step)
    simulation.step();
  const FrameEnergy energy = frame_energy(simulation);
  const Eigen::MatrixXd& p = simulation.positions();
  const Eigen::MatrixXd v = (p - simulation.previous_positions()) / params.dt;
  EXPECT_NEAR(energy.kinetic, 0.5 * (0.5 * v.row(0).squaredNorm() + 1.5 * v.row(1).squaredNorm()),
              1e-12);
  EXPECT_NEAR(energy.gravity, 9.81 * (0.5 * p(0, 1) + 1.5 * p(1, 1)), 1e-12);
  EXPECT_NEAR(energy.spring, 0.5 * params.k * std::pow((p.row(0) - p.row(1)).norm() - 0.3, 2),
              1e-15);
  EXPECT_DOUBLE_EQ(energy.potential, energy.spring + energy.gravity);
  EXPECT_DOUBLE_EQ(energy.total, energy.kinetic + energy.potential);
  // Free fall from rest: the step is pₙ₊₁ = 2pₙ − pₙ₋₁ + Δt² g, so after n steps the fall is
  // g Δt² n(n+1)/2 and the backward-difference speed n Δt g. Kinetic energy ½M g²Δt²n² then
  // trails the potential lost, M g²Δt² n(n+1)/2, by exactly ½M g²Δt² n.
  const double n = 10.0, M = 2.0, g = 9.81;
  EXPECT_NEAR(start.gravity - energy.gravity, M * g * g * params.dt * params.dt * n * (n + 1) / 2,
              1e-9);
  EXPECT_NEAR(energy.kinetic, 0.5 * M * g * g * params.dt * params.dt * n * n, 1e-9);
  EXPECT_NEAR(start.total - energy.total, 0.5 * M * g * g * params.dt * params.dt * n, 1e-9);
}

}  // namespace
}  // namespace wobble

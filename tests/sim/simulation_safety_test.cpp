// A step that goes wrong never reaches the caller's positions: it is rolled back and reported,
// and the extreme settings a curious user can reach keep running.
#include <gtest/gtest.h>

#include "sim/input_error.h"
#include "sim/shapes/cloth_grid.h"
#include "sim/simulation.h"
#include "sim/value_limits.h"
#include "test_meshes.h"

namespace {

using wobble::Simulation;
using wobble::SimulationParams;
using wobble::StepStatus;

SimulationParams plain_params() {
  SimulationParams params = wobble::testing::test_params();
  params.iterations = 20;
  return params;
}

TEST(SimulationSafety, ANonFiniteStepIsRolledBack) {
  const auto mesh = wobble::testing::chain_mesh(3);
  Simulation simulation(mesh.network, {}, plain_params());
  // Finite, but M(2pᵗ − pᵗ⁻ᐞᵗ)/Δt² overflows to infinity.
  const Eigen::MatrixXd current = Eigen::MatrixXd::Constant(4, 3, 1e307);
  const Eigen::MatrixXd previous = Eigen::MatrixXd::Constant(4, 3, -1e307);
  simulation.set_state(current, previous);
  EXPECT_EQ(simulation.step(), StepStatus::not_finite);
  EXPECT_EQ(simulation.last_step_status(), StepStatus::not_finite);
  EXPECT_EQ(simulation.positions(), current);
  EXPECT_EQ(simulation.previous_positions(), previous);
  EXPECT_EQ(simulation.steps_taken(), 0);

  // A sane state steps again.
  simulation.reset();
  EXPECT_EQ(simulation.step(), StepStatus::ok);
  EXPECT_EQ(simulation.steps_taken(), 1);
}

TEST(SimulationSafety, AJumpBeyondTheLimitIsRolledBackAndOneWithinIsNot) {
  // One link of 0.1 m: the rest shape's diagonal is 0.1 m, so the limit is 10 m.
  const auto mesh = wobble::testing::chain_mesh(1);
  SimulationParams params = plain_params();
  params.gravity.setZero();
  Simulation simulation(mesh.network, {0}, params);
  ASSERT_DOUBLE_EQ(simulation.jump_limit(), 10.0);
  const Eigen::MatrixXd before = simulation.positions();

  simulation.set_pin_target(0, Eigen::Vector3d(10.5, 0.0, 0.0));
  EXPECT_EQ(simulation.step(), StepStatus::jumped);
  EXPECT_EQ(simulation.positions(), before);
  EXPECT_EQ(simulation.steps_taken(), 0);

  simulation.set_pin_target(0, Eigen::Vector3d(9.5, 0.0, 0.0));
  EXPECT_EQ(simulation.step(), StepStatus::ok);
  EXPECT_NEAR(simulation.positions()(0, 0), 9.5, 1e-6);
}

TEST(SimulationSafety, FastFreeFallIsNotAJump) {
  // 10 km/s moves every vertex 167 m a step, far beyond the 10 m limit, but exactly where
  // inertia takes it: the limit is on the departure from the inertial prediction.
  const auto mesh = wobble::testing::chain_mesh(1);
  const Eigen::MatrixXd velocity = Eigen::RowVector3d(0.0, -1e4, 0.0).replicate(2, 1);
  Simulation simulation(mesh.network, {}, plain_params(), velocity);
  for (int step = 0; step < 100; ++step)
    ASSERT_EQ(simulation.step(), StepStatus::ok) << "step " << step;
  EXPECT_LT(simulation.positions()(0, 1), -1e4);
}

TEST(SimulationSafety, ExtremeSettingsKeepRunning) {
  const auto mesh = wobble::testing::grid_mesh();
  const long n = mesh.network.V.rows();
  struct Case {
    const char* name;
    double k, dt;
    std::vector<int> pins;
  };
  std::vector<int> every;
  for (int i = 0; i < n; ++i)
    every.push_back(i);
  const Case cases[] = {
      {"stiffest and slowest", 1e6, 1.0 / 15.0, mesh.pins},
      {"softest and fastest", 1.0, 1.0 / 240.0, mesh.pins},
      {"every vertex pinned", 1e6, 1.0 / 15.0, every},
      {"no pins", 1e6, 1.0 / 15.0, {}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    SimulationParams params = plain_params();
    params.k = c.k;
    params.dt = c.dt;
    Simulation simulation(mesh.network, c.pins, params);
    for (int step = 0; step < 200; ++step)
      ASSERT_EQ(simulation.step(), StepStatus::ok) << "step " << step;
    ASSERT_TRUE(simulation.positions().allFinite());
    if (c.pins.size() == static_cast<std::size_t>(n)) {
      EXPECT_LT((simulation.positions() - mesh.network.V).cwiseAbs().maxCoeff(), 1e-6);
    }
  }
}

TEST(SimulationSafety, DescriptionsSayWhatToTry) {
  for (StepStatus status : {StepStatus::not_finite, StepStatus::jumped}) {
    const std::string text = Simulation::describe(status);
    EXPECT_NE(text.find("rolled back"), std::string::npos) << text;
    EXPECT_NE(text.find("smaller dt"), std::string::npos) << text;
    EXPECT_EQ(text.find('\n'), std::string::npos) << text;
  }
}

}  // namespace

// Iterations and mesh size are each within their limits, but not always their product: a step
// of 5,000 iterations of a 256x256 cloth ran past a minute. The bound is computed from this
// mesh's springs and factor, and refusals name both settings.
TEST(SimulationSafety, TheWorkOfAStepIsBoundedByIterationsTimesTheMesh) {
  wobble::ClothGridOptions options;
  options.resolution = 128;
  const wobble::SpringNetwork cloth = wobble::make_cloth_grid(options);
  wobble::SimulationParams params;
  params.iterations = 10;
  wobble::Simulation simulation(cloth, {0}, params);
  const int most = simulation.max_iterations_for_mesh();
  const double per_iteration =
      static_cast<double>(cloth.E.rows()) + static_cast<double>(simulation.factor_nonzeros());
  EXPECT_LE(most * per_iteration, wobble::limits::max_step_work);
  EXPECT_GT((most + 1) * per_iteration, wobble::limits::max_step_work);
  EXPECT_LT(most, wobble::Simulation::max_iterations);  // the product binds before the limit
  EXPECT_NO_THROW(simulation.apply(
      wobble::with_setting(simulation.params(), "iterations", static_cast<double>(most))));
  try {
    simulation.apply(
        wobble::with_setting(simulation.params(), "iterations", static_cast<double>(most + 1)));
    ADD_FAILURE() << "one iteration past the bound was taken";
  } catch (const wobble::InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("iterations and the mesh"), std::string::npos) << message;
    EXPECT_NE(message.find("at most " + std::to_string(most) + " iterations"), std::string::npos)
        << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
  EXPECT_EQ(simulation.params().iterations, most);
  params.iterations = most + 1;
  EXPECT_THROW(wobble::Simulation(cloth, {0}, params), wobble::InputError);
  // The built-in 40x40 cloth takes every iteration the limit allows.
  options.resolution = 40;
  params.iterations = wobble::Simulation::max_iterations;
  EXPECT_EQ(
      wobble::Simulation(wobble::make_cloth_grid(options), {0}, params).max_iterations_for_mesh(),
      wobble::Simulation::max_iterations);
}

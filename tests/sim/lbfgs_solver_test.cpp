// The L-BFGS solver (sim/solver/lbfgs_solver.h) against local-global on the same step: it never
// raises the energy, it reaches local-global's energy in fewer iterations on stiff cloth, it
// finds the same minimum, and it sees every term of the step (pins, gravity, wind, damping,
// contact and friction).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <string>
#include <vector>

#include "sim/contact/collider_contact.h"
#include "sim/contact/collider_contact_term.h"
#include "sim/contact/solve_contact.h"
#include "sim/input_error.h"
#include "sim/shapes/cloth_grid.h"
#include "sim/simulation.h"
#include "test_colliders.h"

namespace {

using wobble::Simulation;
using wobble::SimulationParams;

// A cloth of resolution² vertices, 1 m, pinned along row 0, flat at 1 m, pushed sideways.
struct PushedCloth {
  wobble::SpringNetwork network;
  std::vector<int> pins;
  Eigen::MatrixXd velocity;
};

PushedCloth pushed_cloth(int resolution) {
  wobble::ClothGridOptions options;
  options.resolution = resolution;
  PushedCloth cloth;
  cloth.network = wobble::make_cloth_grid(options);
  cloth.network.V.col(1).array() += 1.0;
  for (int column = 0; column < resolution; ++column)
    cloth.pins.push_back(wobble::cloth_grid_vertex(resolution, 0, column));
  cloth.velocity = Eigen::MatrixXd::Zero(cloth.network.V.rows(), 3);
  for (Eigen::Index i = 0; i < cloth.velocity.rows(); ++i) {
    cloth.velocity(i, 0) = 1.5 * cloth.network.V(i, 2);  // a shear the springs must undo
    cloth.velocity(i, 1) = -1.0;
  }
  for (int pin : cloth.pins)
    cloth.velocity.row(pin).setZero();
  return cloth;
}

// One step of `solver` from the cloth's start: the simulation after it, its trace recorded.
std::unique_ptr<Simulation> one_step(const PushedCloth& cloth, SimulationParams params,
                                     const std::string& solver) {
  params.solver = solver;
  auto simulation = std::make_unique<Simulation>(cloth.network, cloth.pins, params, cloth.velocity);
  simulation->set_convergence_recording(true);
  EXPECT_EQ(simulation->step(), wobble::StepStatus::ok);
  return simulation;
}

void expect_never_rises(const std::vector<double>& energy) {
  for (std::size_t i = 1; i < energy.size(); ++i)
    EXPECT_LE(energy[i], energy[i - 1]) << "iterate " << i;
}

TEST(Lbfgs, OnStiffClothReachesFiftyLocalGlobalIterationsInHalfOfThemWithoutRising) {
  const PushedCloth cloth = pushed_cloth(21);
  SimulationParams params;
  params.k = 1e5;
  params.iterations = 50;
  const auto local_global = one_step(cloth, params, "local-global");
  const auto lbfgs = one_step(cloth, params, "lbfgs");
  const std::vector<double>& plain = local_global->last_convergence().energy;
  const std::vector<double>& quasi_newton = lbfgs->last_convergence().energy;
  ASSERT_EQ(quasi_newton.size(), 51u);
  EXPECT_STREQ(lbfgs->last_convergence().solver, "lbfgs");
  EXPECT_STREQ(local_global->last_convergence().solver, "local-global");
  expect_never_rises(quasi_newton);
  int needed = -1;
  for (std::size_t i = 0; i < quasi_newton.size() && needed < 0; ++i) {
    if (quasi_newton[i] <= plain.back()) needed = static_cast<int>(i);
  }
  std::printf("[ info ] local-global 50: E %.9g; lbfgs reaches it after %d, ends at %.9g\n",
              plain.back(), needed, quasi_newton.back());
  ASSERT_GE(needed, 0);
  EXPECT_LE(needed, 25) << "half of local-global's iterations";
  EXPECT_LT(quasi_newton.back(), plain.back());
}

TEST(Lbfgs, FindsTheSameMinimumAsLocalGlobal) {
  // A soft, small cloth, where local-global converges too (to 1e-13 in 1,000 iterations; at
  // k = 300 on 12×12 it is still at 1e-3 after 400): both end at one minimizer. With damping,
  // wind and a pin moved, so that every term of local-global's Q and y is in L-BFGS's energy.
  const PushedCloth cloth = pushed_cloth(6);
  SimulationParams params;
  params.k = 20.0;
  params.iterations = 1000;
  for (const bool everything : {false, true}) {
    if (everything) {
      params.damping = 0.7;
      params.wind = wobble::WindParams::default_breeze();
    }
    const auto step = [&](const std::string& solver) {
      params.solver = solver;
      auto simulation =
          std::make_unique<Simulation>(cloth.network, cloth.pins, params, cloth.velocity);
      simulation->set_convergence_recording(true);
      if (everything) {
        const int pin = cloth.pins.back();
        simulation->set_pin_target(
            pin, cloth.network.V.row(pin).transpose() + Eigen::Vector3d(0.03, -0.02, 0.01));
      }
      for (int repeat = 0; repeat < 2; ++repeat)
        EXPECT_EQ(simulation->step(), wobble::StepStatus::ok);
      return simulation;
    };
    const auto local_global = step("local-global");
    const auto lbfgs = step("lbfgs");
    const double apart = (local_global->positions() - lbfgs->positions()).cwiseAbs().maxCoeff();
    std::printf("[ info ] %s: %.3g m apart\n", everything ? "every term" : "springs", apart);
    EXPECT_LT(apart, 1e-7) << "m";
    // L-BFGS stops when no step lowers the energy to rounding: here at ‖∇E‖ ≈ 1e-6 N.
    EXPECT_LT(lbfgs->last_convergence().gradient_reduction(), 1e-5);
    EXPECT_LT(local_global->last_convergence().gradient_reduction(), 1e-10);
  }
}

TEST(Lbfgs, SeesEveryTermOfTheStep) {
  // Pins moved, gravity, wind, damping, the ground and friction: the step's minimum is where the
  // whole energy's gradient vanishes, and L-BFGS gets there.
  PushedCloth cloth = pushed_cloth(12);
  cloth.network.V.col(1).array() -= 0.99;  // 1 cm over the ground: it lands in this step
  SimulationParams params;
  params.k = 2000.0;
  params.iterations = 200;
  params.damping = 0.5;
  params.wind = wobble::WindParams::default_breeze();
  params.contact.colliders = {wobble::testing::ground_collider()};
  params.contact.friction = 0.4;
  params.solver = "lbfgs";
  Simulation simulation(cloth.network, cloth.pins, params, cloth.velocity);
  simulation.set_pin_target(
      cloth.pins.front(),
      cloth.network.V.row(cloth.pins.front()).transpose() + Eigen::Vector3d(0.0, 0.02, 0.0));
  simulation.set_convergence_recording(true);
  for (int step = 0; step < 3; ++step) {
    ASSERT_EQ(simulation.step(), wobble::StepStatus::ok);
    const wobble::ConvergenceTrace& trace = simulation.last_convergence();
    expect_never_rises(trace.energy);
    EXPECT_LT(trace.gradient_reduction(), 1e-4) << "step " << step;
  }
  EXPECT_GT(simulation.term<wobble::ColliderContactTerm>()->colliders().contact_count(), 0)
      << "the cloth must have reached the ground";
  EXPECT_NEAR(simulation.positions()(cloth.pins.front(), 1),
              cloth.network.V(cloth.pins.front(), 1) + 0.02, 1e-6);
}

TEST(Lbfgs, SwitchesWithLocalGlobalBetweenSteps) {
  const PushedCloth cloth = pushed_cloth(10);
  SimulationParams params;
  params.iterations = 20;
  Simulation simulation(cloth.network, cloth.pins, params, cloth.velocity);
  simulation.set_convergence_recording(true);
  simulation.step();
  EXPECT_STREQ(simulation.last_convergence().solver, "local-global");
  simulation.apply(wobble::with_setting(simulation.params(), "solver", std::string("lbfgs")));
  EXPECT_EQ(simulation.params().solver, "lbfgs");
  simulation.step();
  EXPECT_STREQ(simulation.last_convergence().solver, "lbfgs");
  simulation.apply(
      wobble::with_setting(simulation.params(), "solver", std::string("local-global")));
  simulation.step();
  EXPECT_STREQ(simulation.last_convergence().solver, "local-global");
  EXPECT_THROW(
      simulation.apply(wobble::with_setting(simulation.params(), "solver", std::string("newton"))),
      wobble::InputError);
}

TEST(SolveContactEnergy, GradientMatchesFiniteDifferences) {
  // Three vertices pressed into the ground and a sphere, sliding, with friction lagged from the
  // state: the analytic gradient of the contact energy against central differences.
  const PushedCloth cloth = pushed_cloth(3);
  wobble::SpringNetwork network = cloth.network;
  network.V.col(1).array() -= 1.0;
  Eigen::MatrixXd current = network.V;
  const Eigen::MatrixXd previous = current;
  std::vector<char> pinned(network.V.rows(), 0);
  const wobble::StepContext step{network, current, previous, pinned, 1.0 / 60.0, 0.0};
  wobble::ColliderContact contact(
      {wobble::testing::ground_collider(),
       wobble::testing::sphere_collider(Eigen::Vector3d(0.5, 0.0, 0.5), 0.2)},
      0.5, 0.01);
  wobble::SolveContact solve;
  solve.set_base_diagonal(Eigen::VectorXd::Constant(network.V.rows(), 1000.0),
                          Eigen::VectorXd::Constant(network.V.rows(), 10.0));
  ASSERT_TRUE(solve.choose(contact, step, current, 0.0));
  Eigen::MatrixXd pressed = current;
  pressed.col(1).array() -= 0.004;  // inside the offset: the members carry a normal force
  solve.record_forces(contact, pressed);
  solve.lag_friction(contact, step);
  Eigen::MatrixXd p = pressed;
  for (Eigen::Index i = 0; i < p.rows(); ++i)
    p(i, 0) += 0.003 * static_cast<double>(i % 3) - 0.002;  // slides, some within Huber's width
  Eigen::MatrixXd gradient = Eigen::MatrixXd::Zero(p.rows(), 3);
  solve.energy(contact, step, p, &gradient);
  const double h = 1e-7;
  for (Eigen::Index i = 0; i < p.rows(); ++i) {
    for (int c = 0; c < 3; ++c) {
      Eigen::MatrixXd plus = p, minus = p;
      plus(i, c) += h;
      minus(i, c) -= h;
      const double numeric = (solve.energy(contact, step, plus, nullptr) -
                              solve.energy(contact, step, minus, nullptr)) /
                             (2.0 * h);
      EXPECT_NEAR(gradient(i, c), numeric, 1e-5 * (1.0 + std::abs(numeric)))
          << "vertex " << i << " axis " << c;
    }
  }
  EXPECT_GT(gradient.cwiseAbs().maxCoeff(), 0.1) << "the check must see a force";
}

}  // namespace

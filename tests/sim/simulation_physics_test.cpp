// Physics of the Simulation: properties of the method and of the motion it produces, checked
// against independently computed answers.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <vector>

#include "sim/shapes/cloth_grid.h"
#include "sim/simulation.h"
#include "test_meshes.h"

namespace {

using wobble::Simulation;
using wobble::SimulationParams;

using wobble::testing::test_params;

TEST(SimulationPhysics, MeshAtRestWithoutGravityStaysAtRest) {
  for (const auto& mesh : wobble::testing::all_test_meshes()) {
    SCOPED_TRACE(mesh.name);
    SimulationParams params = test_params();
    params.gravity.setZero();
    for (const std::vector<int>& pins : {mesh.pins, std::vector<int>{}}) {
      Simulation simulation(mesh.network, pins, params);
      for (int step = 0; step < 100; ++step)
        simulation.step();
      // Every spring is at rest length, so d_e = V_i − V_j and the solve returns V: only
      // rounding can move anything. The right-hand side holds w·V ≈ 1e10 at pinned rows, so
      // each of the 5000 solves may leave ~1e-15 m; 1e-10 m bounds their sum with margin
      // (5e-12 is typical), while any real force would move the mesh by millimetres.
      EXPECT_LE((simulation.positions() - mesh.network.V).cwiseAbs().maxCoeff(), 1e-10);
    }
  }
}

TEST(SimulationPhysics, EveryIterationDoesNotIncreaseTheStepEnergy) {
  // Damping changes the inertia term (and Q): the guarantee must hold with it too.
  for (const double damping : {0.0, 3.0})
    for (const auto& mesh : wobble::testing::all_test_meshes()) {
      SCOPED_TRACE(mesh.name + " damping " + std::to_string(damping));
      wobble::SimulationParams params = test_params();
      params.damping = damping;
      Simulation simulation(mesh.network, mesh.pins, params);
      for (int step = 0; step < 8; ++step)
        simulation.step();  // get moving first
      if (!mesh.pins.empty()) {
        // A moved target puts the pins far from equilibrium: a hard step for the method.
        simulation.set_pin_target(mesh.pins[0], mesh.network.V.row(mesh.pins[0]).transpose() +
                                                    Eigen::Vector3d(0.05, 0.02, 0.0));
      }

      std::vector<double> energies = {simulation.step_energy(simulation.positions())};
      simulation.set_iteration_observer(
          [&](int, const Eigen::MatrixXd& p) { energies.push_back(simulation.step_energy(p)); });
      simulation.step();
      ASSERT_EQ(energies.size(), 51u);
      for (std::size_t i = 1; i < energies.size(); ++i) {
        // Local step and global step each minimize a bound on the energy exactly, so it can only
        // go down; 1e-12 relative allows for the rounding of evaluating it.
        EXPECT_LE(energies[i], energies[i - 1] + 1e-12 * std::max(1.0, std::abs(energies[i - 1])))
            << "iteration " << i - 1;
      }
      EXPECT_LT(energies.back(), energies.front() - 1e-9) << "the step must actually descend";
    }
}

// The step energy, written out independently of the Simulation with its gradient and Hessian,
// minimized by Newton's method with a backtracking line search.
struct StepProblem {
  Eigen::MatrixXd V, current, previous, fext, targets;
  Eigen::MatrixXi E;
  Eigen::VectorXd m;
  std::vector<int> pins;
  double k, dt, w = 1e10;

  double rest(Eigen::Index e) const { return (V.row(E(e, 0)) - V.row(E(e, 1))).norm(); }

  double energy(const Eigen::VectorXd& x) const {
    const auto p = [&](Eigen::Index i) { return Eigen::Vector3d(x.segment<3>(3 * i)); };
    double total = 0.0;
    for (Eigen::Index e = 0; e < E.rows(); ++e) {
      const double stretch = (p(E(e, 0)) - p(E(e, 1))).norm() - rest(e);
      total += 0.5 * k * stretch * stretch;
    }
    for (Eigen::Index i = 0; i < V.rows(); ++i) {
      const Eigen::Vector3d a =
          p(i) - 2.0 * current.row(i).transpose() + previous.row(i).transpose();
      total += 0.5 * m(i) * a.squaredNorm() / (dt * dt) - p(i).dot(fext.row(i));
    }
    for (int i : pins)
      total += 0.5 * w * (p(i) - targets.row(i).transpose()).squaredNorm();
    return total;
  }

  void gradient_and_hessian(const Eigen::VectorXd& x, Eigen::VectorXd& g,
                            Eigen::MatrixXd& H) const {
    const Eigen::Index n = V.rows();
    g = Eigen::VectorXd::Zero(3 * n);
    H = Eigen::MatrixXd::Zero(3 * n, 3 * n);
    const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
    for (Eigen::Index e = 0; e < E.rows(); ++e) {
      const int i = E(e, 0), j = E(e, 1);
      const Eigen::Vector3d d = x.segment<3>(3 * i) - x.segment<3>(3 * j);
      const double l = d.norm();
      const Eigen::Vector3d u = d / l;
      const Eigen::Vector3d force = k * (l - rest(e)) * u;
      // ∂²/∂d² of ½k(‖d‖ − r)² = k (uuᵀ + (1 − r/l)(I − uuᵀ))
      const Eigen::Matrix3d block =
          k * (u * u.transpose() + (1.0 - rest(e) / l) * (I - u * u.transpose()));
      g.segment<3>(3 * i) += force;
      g.segment<3>(3 * j) -= force;
      H.block<3, 3>(3 * i, 3 * i) += block;
      H.block<3, 3>(3 * j, 3 * j) += block;
      H.block<3, 3>(3 * i, 3 * j) -= block;
      H.block<3, 3>(3 * j, 3 * i) -= block;
    }
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::Vector3d a =
          x.segment<3>(3 * i) - 2.0 * current.row(i).transpose() + previous.row(i).transpose();
      g.segment<3>(3 * i) += m(i) * a / (dt * dt) - fext.row(i).transpose();
      H.block<3, 3>(3 * i, 3 * i) += (m(i) / (dt * dt)) * I;
    }
    for (int i : pins) {
      g.segment<3>(3 * i) += w * (x.segment<3>(3 * i) - targets.row(i).transpose());
      H.block<3, 3>(3 * i, 3 * i) += w * I;
    }
  }

  Eigen::MatrixXd newton_minimizer() const {
    Eigen::VectorXd x(3 * V.rows());
    for (Eigen::Index i = 0; i < V.rows(); ++i)
      x.segment<3>(3 * i) = current.row(i).transpose();
    Eigen::VectorXd g;
    Eigen::MatrixXd H;
    for (int iteration = 0; iteration < 100; ++iteration) {
      gradient_and_hessian(x, g, H);
      const Eigen::VectorXd direction = -H.ldlt().solve(g);
      if (direction.norm() < 1e-15) break;
      double step = 1.0;
      const double start = energy(x);
      while (energy(x + step * direction) > start + 1e-4 * step * g.dot(direction) &&
             step > 1e-10) {
        step *= 0.5;
      }
      x += step * direction;
    }
    Eigen::MatrixXd p(V.rows(), 3);
    for (Eigen::Index i = 0; i < V.rows(); ++i)
      p.row(i) = x.segment<3>(3 * i).transpose();
    return p;
  }
};

void expect_converges_to_newton(const wobble::SpringNetwork& network, const std::vector<int>& pins,
                                const Eigen::MatrixXd& initial_velocity) {
  SimulationParams params;
  params.k = 50.0;
  params.dt = 1.0 / 60.0;
  params.iterations = 5;
  Simulation simulation(network, pins, params, initial_velocity);
  for (int step = 0; step < 5; ++step)
    simulation.step();
  if (!pins.empty()) {
    simulation.set_pin_target(pins[0],
                              network.V.row(pins[0]).transpose() + Eigen::Vector3d(0, 0.03, 0.02));
  }

  StepProblem problem;
  problem.V = network.V;
  problem.E = network.E;
  problem.m = network.m;
  problem.pins = pins;
  problem.k = params.k;
  problem.dt = params.dt;
  problem.current = simulation.positions();
  problem.previous = simulation.previous_positions();
  problem.fext = simulation.external_forces();
  problem.targets = network.V;
  for (int i : pins)
    problem.targets.row(i) = simulation.pin_target(i).transpose();
  const Eigen::MatrixXd newton = problem.newton_minimizer();

  simulation.apply(wobble::with_setting(simulation.params(), "iterations", 2000.0));
  simulation.step();
  const Eigen::MatrixXd& local_global = simulation.positions();
  EXPECT_LE((local_global - newton).cwiseAbs().maxCoeff(), 1e-8);
  // Not vacuous: the minimizer is far from where the step started.
  EXPECT_GT((newton - problem.current).cwiseAbs().maxCoeff(), 1e-4);
}

TEST(SimulationPhysics, SingleSpringConvergesToTheNewtonMinimizer) {
  wobble::SpringNetwork spring;
  spring.V.resize(2, 3);
  spring.V << 0, 1, 0, 0.2, 1, 0;
  spring.E.resize(1, 2);
  spring.E << 0, 1;
  spring.m = Eigen::Vector2d(0.05, 0.08);
  Eigen::MatrixXd velocity(2, 3);
  velocity << -0.5, 0.2, 0.1, 0.7, 0.0, -0.3;  // flying apart and spinning
  expect_converges_to_newton(spring, {}, velocity);
}

TEST(SimulationPhysics, ChainConvergesToTheNewtonMinimizer) {
  const auto chain = wobble::testing::chain_mesh(4);
  Eigen::MatrixXd velocity = Eigen::MatrixXd::Zero(5, 3);
  velocity.col(2) = Eigen::VectorXd::LinSpaced(5, 0.0, 1.0);  // swinging sideways
  expect_converges_to_newton(chain.network, chain.pins, velocity);
}

TEST(SimulationPhysics, HangingClothSags) {
  wobble::ClothGridOptions options;
  options.resolution = 10;
  const wobble::SpringNetwork cloth = wobble::make_cloth_grid(options);
  const int n = options.resolution;
  const int left = wobble::cloth_grid_vertex(n, 0, 0),
            right = wobble::cloth_grid_vertex(n, 0, n - 1);
  SimulationParams params = test_params();
  params.k = 100.0;
  Simulation simulation(cloth, {left, right}, params);
  for (int step = 0; step < 600; ++step)
    simulation.step();
  const Eigen::MatrixXd& p = simulation.positions();

  EXPECT_LE((p.row(left) - cloth.V.row(left)).norm(), 1e-6);
  EXPECT_LE((p.row(right) - cloth.V.row(right)).norm(), 1e-6);
  // It hangs: the far edge, 1 m of cloth away from the pins, now lies below them...
  for (int column = 0; column < n; ++column) {
    EXPECT_LT(p(wobble::cloth_grid_vertex(n, n - 1, column), 1), -0.7) << "column " << column;
  }
  // ...and the top edge sags between the two pinned corners, lowest in the middle.
  const auto top = [&](int column) { return p(wobble::cloth_grid_vertex(n, 0, column), 1); };
  const double middle_of_top = 0.5 * (top(n / 2 - 1) + top(n / 2));
  EXPECT_LT(middle_of_top, -0.005);
  EXPECT_LT(middle_of_top, top(2));
  EXPECT_LT(middle_of_top, top(n - 3));
  EXPECT_LT(p.col(1).maxCoeff(), 1e-6) << "nothing rises above the pins";
}

TEST(SimulationPhysics, ChangingDtKeepsVelocity) {
  const auto mesh = wobble::testing::grid_mesh();
  Simulation simulation(mesh.network, mesh.pins, test_params());
  for (int step = 0; step < 15; ++step)
    simulation.step();
  const Eigen::MatrixXd before = simulation.velocities();
  const Eigen::MatrixXd positions = simulation.positions();
  ASSERT_GT(before.cwiseAbs().maxCoeff(), 0.1) << "the cloth must be moving";
  simulation.apply(wobble::with_setting(simulation.params(), "dt", 1.0 / 240.0));
  EXPECT_EQ(simulation.positions(), positions);
  EXPECT_LE((simulation.velocities() - before).cwiseAbs().maxCoeff(), 1e-9);
  // A quarter of the old step later the cloth has moved about a quarter as far.
  simulation.step();
  const double expected = (before * (1.0 / 240.0)).cwiseAbs().maxCoeff();
  const double moved = (simulation.positions() - positions).cwiseAbs().maxCoeff();
  EXPECT_NEAR(moved, expected, 0.25 * expected);
}

TEST(SimulationPhysics, MovingAPinTargetMovesThePinnedVertexThere) {
  const auto mesh = wobble::testing::grid_mesh();
  Simulation simulation(mesh.network, mesh.pins, test_params());
  const int pin = mesh.pins[0];
  const int neighbour = pin + 1;
  const Eigen::Vector3d target =
      mesh.network.V.row(pin).transpose() + Eigen::Vector3d(-0.3, 0.2, 0.1);
  simulation.set_pin_target(pin, target);
  simulation.step();
  EXPECT_LE((simulation.positions().row(pin).transpose() - target).norm(), 1e-6);
  for (int step = 0; step < 30; ++step)
    simulation.step();
  EXPECT_LE((simulation.positions().row(pin).transpose() - target).norm(), 1e-6);
  // The cloth follows: the pin's neighbour is pulled the same way.
  EXPECT_LT(simulation.positions()(neighbour, 0), mesh.network.V(neighbour, 0) - 0.1);
}

}  // namespace

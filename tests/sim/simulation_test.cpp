// The Simulation object's contract: same positions as the seed, and the promised cost of each
// change (which ones re-factorize, which never re-analyse).
#include "sim/simulation.h"

#include <gtest/gtest.h>

#include "sim/input_error.h"
#include "sim/seed/fast_mass_springs_precomputation_sparse.h"
#include "sim/seed/fast_mass_springs_step_sparse.h"
#include "sim/solver/solver_registry.h"
#include "test_meshes.h"

namespace {

using wobble::InputError;
using wobble::Simulation;
using wobble::SimulationParams;
using wobble::testing::all_test_meshes;

using wobble::testing::test_params;

void expect_matches_the_seed(const std::vector<wobble::testing::TestMesh>& meshes) {
  for (const auto& mesh : meshes) {
    SCOPED_TRACE(mesh.name);
    const auto& net = mesh.network;
    SimulationParams params = test_params();
    params.first_iterate = wobble::FirstIterate::current_positions;  // as the seed starts
    Simulation simulation(net, mesh.pins, params);

    const Eigen::VectorXi b = wobble::testing::pin_vector(mesh.pins);
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> M, A, C;
    Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> llt;
    ASSERT_TRUE(fast_mass_springs_precomputation_sparse(net.V, net.E, params.k, net.m, b, params.dt,
                                                        r, M, A, C, llt));
    const Eigen::MatrixXd fext = wobble::testing::gravity_forces(net.m);
    Eigen::MatrixXd prev = net.V, cur = net.V, next;
    for (int step = 0; step < 60; ++step) {
      fast_mass_springs_step_sparse(net.V, net.E, params.k, b, params.dt, fext, r, M, A, C, llt,
                                    prev, cur, next);
      simulation.step();
      // Same system, same ordering, sums in a different order: rounding only.
      ASSERT_LE((simulation.positions() - next).cwiseAbs().maxCoeff(), 1e-9) << "step " << step;
      prev = cur;
      cur = next;
    }
    EXPECT_EQ(simulation.steps_taken(), 60);
  }
}

TEST(Simulation, WithTargetsAtRestMatchesTheSeedSparseStep) {
  expect_matches_the_seed(all_test_meshes());
}

TEST(Simulation, ARepeatedSpringCountsTwiceAsInTheSeed) {
  wobble::testing::TestMesh mesh = wobble::testing::chain_mesh(6);
  Eigen::MatrixXi& E = mesh.network.E;
  E.conservativeResize(E.rows() + 2, 2);
  E.row(E.rows() - 2) = E.row(0);
  E.row(E.rows() - 1) << E(2, 1), E(2, 0);  // the same spring, ends swapped
  expect_matches_the_seed({mesh});
}

TEST(Simulation, ExternalForcesFollowTheGravityModel) {
  const auto mesh = wobble::testing::grid_mesh();
  Simulation simulation(mesh.network, mesh.pins, test_params());
  EXPECT_LE((simulation.external_forces() - wobble::testing::gravity_forces(mesh.network.m))
                .cwiseAbs()
                .maxCoeff(),
            1e-15);
  simulation.apply(wobble::with_setting(
      wobble::with_setting(simulation.params(), "gravity", Eigen::Vector3d(0, -9.8, 0)),
      "gravity-model", std::string("force_per_vertex")));
  for (Eigen::Index i = 0; i < mesh.network.V.rows(); ++i) {
    EXPECT_EQ(simulation.external_forces().row(i), Eigen::RowVector3d(0, -9.8, 0));
  }
}

TEST(Simulation, TargetMovesNeverFactorizeWhilePinsAndParametersDo) {
  const auto mesh = wobble::testing::grid_mesh();
  Simulation simulation(mesh.network, mesh.pins, test_params());
  EXPECT_EQ(simulation.symbolic_analyses(), 1);
  EXPECT_EQ(simulation.numeric_factorizations(), 1);

  simulation.set_pin_target(mesh.pins[0], Eigen::Vector3d(0.1, 0.2, 0.3));
  simulation.step();
  simulation.apply(wobble::with_setting(simulation.params(), "iterations", 10.0));
  simulation.apply(wobble::with_setting(
      wobble::with_setting(simulation.params(), "gravity", Eigen::Vector3d(0, -1, 0)),
      "gravity-model", std::string("acceleration")));
  simulation.step();
  EXPECT_EQ(simulation.numeric_factorizations(), 1) << "target moves and steps must not factorize";

  simulation.pin(14);
  EXPECT_EQ(simulation.numeric_factorizations(), 2);
  simulation.pin(14);  // already pinned: nothing to do
  EXPECT_EQ(simulation.numeric_factorizations(), 2);
  simulation.unpin(14);
  EXPECT_EQ(simulation.numeric_factorizations(), 3);
  simulation.apply(wobble::with_setting(simulation.params(), "k", 500.0));
  EXPECT_EQ(simulation.numeric_factorizations(), 4);
  simulation.apply(wobble::with_setting(simulation.params(), "dt", 1.0 / 120.0));
  EXPECT_EQ(simulation.numeric_factorizations(), 5);
  EXPECT_EQ(simulation.symbolic_analyses(), 1) << "the pattern never changes";
}

TEST(Simulation, RefactorizedSystemMatchesAFreshOne) {
  // A simulation whose k, dt and pins were changed must step exactly like one built that way.
  const auto mesh = wobble::testing::grid_mesh();
  SimulationParams params = test_params();
  Simulation changed(mesh.network, {0}, params);
  changed.apply(wobble::with_setting(changed.params(), "k", 700.0));
  changed.apply(wobble::with_setting(changed.params(), "dt", 1.0 / 90.0));
  changed.pin(5);
  params.k = 700.0;
  params.dt = 1.0 / 90.0;
  Simulation fresh(mesh.network, {0, 5}, params);
  for (int step = 0; step < 20; ++step) {
    changed.step();
    fresh.step();
  }
  EXPECT_LE((changed.positions() - fresh.positions()).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(Simulation, PinHoldsAVertexWhereItIsAndUnpinReleasesIt) {
  const auto mesh = wobble::testing::grid_mesh();
  Simulation simulation(mesh.network, mesh.pins, test_params());
  for (int step = 0; step < 10; ++step)
    simulation.step();
  const int vertex = 33;  // bottom row, falling
  const Eigen::RowVector3d held = simulation.positions().row(vertex);
  simulation.pin(vertex);
  EXPECT_TRUE(simulation.is_pinned(vertex));
  EXPECT_EQ(simulation.pin_count(), 3);
  EXPECT_EQ(simulation.pin_target(vertex), held.transpose());
  for (int step = 0; step < 20; ++step)
    simulation.step();
  EXPECT_LE((simulation.positions().row(vertex) - held).norm(), 1e-6);

  simulation.unpin(vertex);
  EXPECT_FALSE(simulation.is_pinned(vertex));
  for (int step = 0; step < 20; ++step)
    simulation.step();
  EXPECT_GT((simulation.positions().row(vertex) - held).norm(), 1e-3) << "released: it moves";
  EXPECT_EQ(simulation.pinned_vertices(), mesh.pins);
}

TEST(Simulation, ResetRestoresRestStateAndInitialPins) {
  const auto mesh = wobble::testing::grid_mesh();
  Simulation simulation(mesh.network, mesh.pins, test_params());
  for (int step = 0; step < 10; ++step)
    simulation.step();
  simulation.pin(20);
  simulation.unpin(mesh.pins[0]);
  simulation.set_pin_target(mesh.pins[1], Eigen::Vector3d(1, 1, 1));
  simulation.reset();
  EXPECT_EQ(simulation.positions(), mesh.network.V);
  EXPECT_EQ(simulation.previous_positions(), mesh.network.V);
  EXPECT_EQ(simulation.pinned_vertices(), mesh.pins);
  EXPECT_EQ(simulation.pin_target(mesh.pins[1]), mesh.network.V.row(mesh.pins[1]).transpose());
  EXPECT_EQ(simulation.steps_taken(), 0);
  EXPECT_EQ(simulation.symbolic_analyses(), 1);

  // After a reset it steps exactly like a new simulation.
  Simulation fresh(mesh.network, mesh.pins, test_params());
  simulation.step();
  fresh.step();
  EXPECT_LE((simulation.positions() - fresh.positions()).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(Simulation, InitialVelocityIsRestoredByReset) {
  const auto mesh = wobble::testing::chain_mesh(2);
  Eigen::MatrixXd velocity = Eigen::MatrixXd::Zero(3, 3);
  velocity.col(2).setConstant(0.5);
  Simulation simulation(mesh.network, {}, test_params(), velocity);
  EXPECT_LE((simulation.velocities() - velocity).cwiseAbs().maxCoeff(), 1e-12);
  simulation.step();
  simulation.reset();
  EXPECT_LE((simulation.velocities() - velocity).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(Simulation, SolverIsChosenByItsRegisteredName) {
  const auto mesh = wobble::testing::chain_mesh(3);
  SimulationParams params = test_params();
  EXPECT_EQ(params.solver, "local-global");  // the default, registered first
  EXPECT_EQ(std::string(wobble::registered_step_solvers().front().name), "local-global");
  params.solver = "no such solver";
  try {
    Simulation simulation(mesh.network, {}, params);
    FAIL() << "an unknown solver was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("\"local-global\""), std::string::npos)
        << error.what();
  }

  // Switching solvers keeps the state, and steps on as a fresh solver would.
  params = test_params();
  Simulation switched(mesh.network, {0}, params), fresh(mesh.network, {0}, params);
  switched.step();
  fresh.step();
  switched.apply(wobble::with_setting(switched.params(), "solver", std::string("local-global")));
  EXPECT_EQ(switched.positions(), fresh.positions());
  switched.step();
  fresh.step();
  EXPECT_EQ(switched.positions(), fresh.positions());
  EXPECT_THROW(switched.apply(wobble::with_setting(switched.params(), "solver",
                                                   std::string("no such solver"))),
               InputError);
  EXPECT_EQ(switched.params().solver, "local-global");
}

TEST(Simulation, RefusesBadInputWithTypedErrors) {
  const auto mesh = wobble::testing::chain_mesh(3);
  SimulationParams params = test_params();
  EXPECT_THROW(Simulation(mesh.network, {7}, params), InputError);
  EXPECT_THROW(Simulation(mesh.network, {-1}, params), InputError);
  params.k = -1.0;
  EXPECT_THROW(Simulation(mesh.network, {}, params), InputError);
  params = test_params();
  params.dt = 0.0;
  EXPECT_THROW(Simulation(mesh.network, {}, params), InputError);
  params = test_params();
  params.iterations = 0;
  EXPECT_THROW(Simulation(mesh.network, {}, params), InputError);
  params.iterations = Simulation::max_iterations + 1;
  EXPECT_THROW(Simulation(mesh.network, {}, params), InputError);
  EXPECT_THROW(Simulation(mesh.network, {}, test_params(), Eigen::MatrixXd::Zero(2, 3)),
               InputError);

  Simulation simulation(mesh.network, {0}, test_params());
  EXPECT_THROW(simulation.apply(wobble::with_setting(simulation.params(), "k",
                                                     std::numeric_limits<double>::quiet_NaN())),
               InputError);
  EXPECT_THROW(simulation.apply(wobble::with_setting(simulation.params(), "dt", -0.01)),
               InputError);
  EXPECT_THROW(simulation.apply(wobble::with_setting(simulation.params(), "iterations", 0.0)),
               InputError);
  EXPECT_THROW(simulation.pin(4), std::out_of_range);
  EXPECT_THROW(simulation.set_pin_target(2, Eigen::Vector3d::Zero()), std::invalid_argument);
  // A refused change leaves the simulation as it was.
  EXPECT_EQ(simulation.params().k, 200.0);
  EXPECT_EQ(simulation.params().dt, 1.0 / 60.0);
  EXPECT_EQ(simulation.numeric_factorizations(), 1);
}

TEST(Simulation, SetStateReplacesPositionsAndRefusesBadShapes) {
  const auto mesh = wobble::testing::chain_mesh(2);
  Simulation simulation(mesh.network, {}, test_params());
  Eigen::MatrixXd moved = mesh.network.V;
  moved.col(1).setConstant(0.5);
  simulation.set_state(moved, mesh.network.V);
  EXPECT_EQ(simulation.positions(), moved);
  EXPECT_NEAR(simulation.velocities()(0, 1), 0.5 / test_params().dt, 1e-9);
  EXPECT_THROW(simulation.set_state(Eigen::MatrixXd::Zero(2, 3), moved), InputError);
  moved(1, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(simulation.set_state(moved, moved), InputError);
  EXPECT_EQ(simulation.positions().col(1), Eigen::VectorXd::Constant(3, 0.5)) << "unchanged";
}

TEST(Simulation, CollapsedSpringPushesApartAlongItsRestDirection) {
  // Both ends of a spring exactly on one point: the local step has no direction to use.
  const auto mesh = wobble::testing::chain_mesh(1);
  SimulationParams params = test_params();
  params.gravity.setZero();
  Simulation simulation(mesh.network, {}, params);
  const Eigen::MatrixXd collapsed = Eigen::MatrixXd::Constant(2, 3, 0.05);
  simulation.set_state(collapsed, collapsed);
  simulation.step();
  const Eigen::MatrixXd& p = simulation.positions();
  ASSERT_TRUE(p.allFinite());
  // The rest vector V_0 − V_1 points along −x: the ends separate along x and nowhere else.
  EXPECT_LT(p(0, 0), p(1, 0) - 1e-3);
  EXPECT_NEAR(p(0, 1), p(1, 1), 1e-12);
  EXPECT_NEAR(p(0, 2), p(1, 2), 1e-12);
}

TEST(Simulation, PinsDraggedOntoOnePointStayFinite) {
  const auto mesh = wobble::testing::chain_mesh(2);
  Simulation simulation(mesh.network, {0, 1}, test_params());
  simulation.set_pin_target(0, Eigen::Vector3d(0.05, 0, 0));
  simulation.set_pin_target(1, Eigen::Vector3d(0.05, 0, 0));
  for (int step = 0; step < 5; ++step) {
    simulation.step();
    ASSERT_TRUE(simulation.positions().allFinite()) << "step " << step;
  }
  EXPECT_LE((simulation.positions().row(0) - simulation.positions().row(1)).norm(), 1e-6);
}

}  // namespace

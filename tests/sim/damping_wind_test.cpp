// Damping folded into the inertia term, and the two winds: aerodynamic per triangle and the
// course program's.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "sim/forces/wind.h"
#include "sim/input_error.h"
#include "sim/shapes/cloth_grid.h"
#include "sim/simulation.h"
#include "test_meshes.h"

namespace {

using wobble::Simulation;
using wobble::SimulationParams;
using wobble::WindParams;

TEST(Damping, VelocityDecaysAsTheFormulaSays) {
  // A chain moving as a whole, without gravity: the springs stay at rest length, so damping is
  // the only force.
  const wobble::testing::TestMesh chain = wobble::testing::chain_mesh(5);
  const Eigen::Index n = chain.network.V.rows();
  const Eigen::MatrixXd velocity = Eigen::RowVector3d(1.0, 0.5, -0.25).replicate(n, 1);
  for (const double c : {0.5, 1.0, 3.0}) {
    SimulationParams params = wobble::testing::test_params();
    params.gravity.setZero();
    params.damping = c;
    Simulation simulation(chain.network, {}, params, velocity);
    const int steps = 60;  // 1 s
    for (int step = 0; step < steps; ++step)
      ASSERT_EQ(simulation.step(), wobble::StepStatus::ok);
    const double ratio = simulation.velocities().row(0).norm() / velocity.row(0).norm();
    // Implicit Euler: exactly (1 + cΔt)⁻ⁿ, up to the solve's rounding.
    EXPECT_NEAR(ratio, std::pow(1.0 + c * params.dt, -steps), 1e-6) << "c = " << c;
    // And, where cΔt is small, within 5% of the continuous exp(−ct).
    if (c <= 1.0) {
      EXPECT_NEAR(ratio / std::exp(-c * 1.0), 1.0, 0.05) << "c = " << c;
    }
  }
}

TEST(Damping, IsANumericRefactorizationOnlyWhenItChanges) {
  const wobble::testing::TestMesh grid = wobble::testing::grid_mesh();
  Simulation simulation(grid.network, grid.pins, wobble::testing::test_params());
  const int before = simulation.numeric_factorizations();
  simulation.apply(wobble::with_setting(simulation.params(), "damping", 2.0));
  EXPECT_EQ(simulation.numeric_factorizations(), before + 1);
  simulation.apply(wobble::with_setting(simulation.params(), "damping", 2.0));
  EXPECT_EQ(simulation.numeric_factorizations(), before + 1);
  EXPECT_EQ(simulation.symbolic_analyses(), 1);
  EXPECT_THROW(simulation.apply(wobble::with_setting(simulation.params(), "damping", -1.0)),
               wobble::InputError);
  EXPECT_THROW(simulation.apply(wobble::with_setting(simulation.params(), "damping", std::nan(""))),
               wobble::InputError);
  // Damping slows a swinging cloth: less kinetic energy after a second.
  Simulation damped(grid.network, grid.pins, wobble::testing::test_params());
  damped.apply(wobble::with_setting(damped.params(), "damping", 4.0));
  Simulation free(grid.network, grid.pins, wobble::testing::test_params());
  double damped_motion = 0.0, free_motion = 0.0;  // Σ‖v‖² over the second half-second
  for (int step = 0; step < 60; ++step) {
    damped.step();
    free.step();
    if (step >= 30) {
      damped_motion += damped.velocities().squaredNorm();
      free_motion += free.velocities().squaredNorm();
    }
  }
  EXPECT_LT(damped_motion, 0.5 * free_motion);
}

// One triangle, three unit masses, everything explicit.
wobble::SpringNetwork triangle() {
  wobble::SpringNetwork network;
  network.V.resize(3, 3);
  network.V << 0, 0, 0, 1, 0, 0, 0, 1, 0;  // in the xy plane: normal +z, area 0.5
  network.E.resize(3, 2);
  network.E << 0, 1, 1, 2, 2, 0;
  network.F.resize(1, 3);
  network.F << 0, 1, 2;
  network.m = Eigen::VectorXd::Ones(3);
  return network;
}

TEST(Wind, DragPushesAFaceAlongItsNormalAndLiftActsAcrossTheFlow) {
  const wobble::SpringNetwork network = triangle();
  const std::vector<char> pinned(3, 0);
  const wobble::StepContext at_rest{network, network.V, network.V, pinned, 0.01, 0.0};
  WindParams wind;
  wind.on = true;
  wind.drag = 1.2;
  wind.lift = 0.5;
  wind.air_density = 1.25;

  // Face-on: pure drag ½ρC_dA|u·n|(u·n) n, no lift.
  wind.velocity = Eigen::Vector3d(0, 0, 4);
  Eigen::MatrixXd f = Eigen::MatrixXd::Zero(3, 3);
  wobble::AerodynamicWind(wind).add_forces(at_rest, f);
  const double drag = 0.5 * 1.25 * 1.2 * 0.5 * 16.0;
  for (int corner = 0; corner < 3; ++corner) {
    EXPECT_NEAR((f.row(corner) - Eigen::RowVector3d(0, 0, drag / 3)).norm(), 0.0, 1e-12);
  }

  // Edge-on: nothing.
  wind.velocity = Eigen::Vector3d(3, -2, 0);
  f.setZero();
  wobble::AerodynamicWind(wind).add_forces(at_rest, f);
  EXPECT_LT(f.norm(), 1e-12);

  // At 45°: drag along n and lift across u; their sum has no part along u from the lift.
  wind.velocity = Eigen::Vector3d(3, 0, 3);
  f.setZero();
  wobble::AerodynamicWind(wind).add_forces(at_rest, f);
  const Eigen::Vector3d total = 3.0 * f.row(0).transpose();
  const Eigen::Vector3d u = wind.velocity, n(0, 0, 1), along = u.normalized();
  const double un = u.dot(n);
  const Eigen::Vector3d expected_drag = 0.5 * 1.25 * 1.2 * 0.5 * un * un * n;
  const Eigen::Vector3d expected_lift =
      0.5 * 1.25 * 0.5 * 0.5 * un * u.norm() * (n - n.dot(along) * along);
  EXPECT_NEAR((total - expected_drag - expected_lift).norm(), 0.0, 1e-12);
  EXPECT_NEAR(expected_lift.dot(u), 0.0, 1e-12);
  EXPECT_GT(expected_lift.norm(), 0.1);

  // A face moving with the air feels nothing.
  wind.velocity = Eigen::Vector3d(0, 0, 4);
  const Eigen::MatrixXd behind = network.V.rowwise() - Eigen::RowVector3d(0, 0, 0.04);
  const wobble::StepContext moving{network, network.V, behind, pinned, 0.01, 0.0};
  f.setZero();
  wobble::AerodynamicWind(wind).add_forces(moving, f);
  EXPECT_LT(f.norm(), 1e-12);
}

// A vertical 1 m sheet in the xy plane hanging from its top edge.
wobble::SpringNetwork hanging_sheet() {
  wobble::ClothGridOptions options;
  options.resolution = 16;
  wobble::SpringNetwork sheet = wobble::make_cloth_grid(options);
  // Rotate the flat (xz) grid upright: z becomes −y, so row 0 is the top edge.
  const Eigen::VectorXd z = sheet.V.col(2);
  sheet.V.col(2).setZero();
  sheet.V.col(1) = 1.5 - z.array();
  return sheet;
}

double mean_displacement(const WindParams& wind) {
  const wobble::SpringNetwork sheet = hanging_sheet();
  std::vector<int> top;
  for (int column = 0; column < 16; ++column)
    top.push_back(wobble::cloth_grid_vertex(16, 0, column));
  SimulationParams params = wobble::testing::test_params();
  params.wind = wind;
  Simulation simulation(sheet, top, params);
  for (int step = 0; step < 60; ++step)
    EXPECT_EQ(simulation.step(), wobble::StepStatus::ok);
  return (simulation.positions() - sheet.V).rowwise().norm().mean();
}

TEST(Wind, ASheetFacingTheWindBillowsAndOneEdgeOnBarelyMoves) {
  WindParams wind;
  wind.on = true;
  wind.velocity = Eigen::Vector3d(0, 0, 6);  // along the sheet's normal
  const double facing = mean_displacement(wind);
  wind.velocity = Eigen::Vector3d(6, 0, 0);  // along the sheet
  const double edge_on = mean_displacement(wind);
  wind.on = false;
  const double calm = mean_displacement(wind);
  EXPECT_GT(facing, 0.15);
  EXPECT_LT(edge_on, 0.1 * facing);
  EXPECT_LT(std::abs(edge_on - calm), 0.01);
}

TEST(Wind, GustsAreAFunctionOfTimeAndPlaceAlone) {
  WindParams wind;
  wind.on = true;
  wind.velocity = Eigen::Vector3d(5, 0, 0);
  wind.gusts = 0.5;
  double low = 1e9, high = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const double speed = wobble::wind_velocity_at(wind, Eigen::Vector3d::Zero(), 0.01 * i).norm();
    low = std::min(low, speed);
    high = std::max(high, speed);
  }
  EXPECT_GE(low, 2.5 - 1e-12);
  EXPECT_LE(high, 7.5 + 1e-12);
  EXPECT_GT(high - low, 2.0) << "gusts must vary";
  // A gust travels downwind: what is at x = 0 at time t is at x = 5 m one second later.
  EXPECT_NEAR((wobble::wind_velocity_at(wind, Eigen::Vector3d(5, 0, 0), 2.0) -
               wobble::wind_velocity_at(wind, Eigen::Vector3d::Zero(), 1.0))
                  .norm(),
              0.0, 1e-12);
  // Two runs of a gusty flag are identical.
  const double first = mean_displacement(wind), second = mean_displacement(wind);
  EXPECT_EQ(first, second);
}

TEST(Wind, TheCourseWindFollowsTheProgramsFormulaWithSimulatedTime) {
  const wobble::testing::TestMesh grid = wobble::testing::grid_mesh();
  const wobble::SpringNetwork& net = grid.network;
  const std::vector<char> pinned(net.V.rows(), 0);
  Eigen::MatrixXd current = net.V;
  current.col(0).array() += 0.3;
  const double diagonal = (net.V.colwise().maxCoeff() - net.V.colwise().minCoeff()).norm();
  const double time = 0.7;
  const wobble::StepContext step{net, current, net.V, pinned, 1.0 / 30.0, time};
  Eigen::MatrixXd f = Eigen::RowVector3d(0.5, -9.8, 0.25).replicate(net.V.rows(), 1);
  wobble::CourseWind(diagonal).add_forces(step, f);
  for (Eigen::Index i = 0; i < f.rows(); ++i) {
    const double phi = current(i, 0) / diagonal + time;
    EXPECT_DOUBLE_EQ(f(i, 0), 3.0 + 1.5 * (1.0 + std::cos(5.0 * phi)));
    EXPECT_DOUBLE_EQ(f(i, 1), -9.8 + 1.0 + std::cos(0.3 + phi));
    EXPECT_DOUBLE_EQ(f(i, 2), std::sin(phi));
  }
}

TEST(Wind, NeverRefactorizesAndTurnsOff) {
  const wobble::testing::TestMesh grid = wobble::testing::grid_mesh();
  SimulationParams params = wobble::testing::test_params();
  Simulation simulation(grid.network, grid.pins, params);
  const int before = simulation.numeric_factorizations();
  simulation.apply([&] {
    wobble::SimulationParams changed = simulation.params();
    changed.wind = WindParams::default_breeze();
    return changed;
  }());
  for (int step = 0; step < 20; ++step)
    simulation.step();
  const Eigen::MatrixXd windy = simulation.external_forces();
  simulation.apply([&] {
    wobble::SimulationParams changed = simulation.params();
    changed.wind = WindParams();
    return changed;
  }());
  simulation.step();
  EXPECT_EQ(simulation.numeric_factorizations(), before);
  // Off again: gravity alone.
  const Eigen::MatrixXd gravity = wobble::testing::gravity_forces(grid.network.m);
  EXPECT_LT((simulation.external_forces() - gravity).norm(), 1e-15);
  EXPECT_GT((windy - gravity).norm(), 1e-3);
  WindParams wild = WindParams::default_breeze();
  wild.gusts = 3.0;
  EXPECT_THROW(simulation.apply([&] {
    wobble::SimulationParams changed = simulation.params();
    changed.wind = wild;
    return changed;
  }()),
               wobble::InputError);
}

}  // namespace

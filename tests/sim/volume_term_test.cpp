// The volume term (sim/volume/volume_term.h): a jelly turned inside out comes back. The issue's
// drag and two harsher cases, with and without the term, for both solvers: the root-mean-square
// distance from the best rigid placement of the rest shape, over its bounding-box diagonal, 2 s
// after release, and the tetrahedra still inverted then. And the term's own parts: the nearest
// rotation of an inverted F, and its energy's gradient against finite differences.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "sim/contact/collider.h"
#include "sim/contact/collider_contact_term.h"
#include "sim/instruments/rigid_fit.h"
#include "sim/settings/setting_registry.h"
#include "sim/shapes/builtin_scenes.h"
#include "sim/shapes/jelly_block.h"
#include "sim/simulation.h"
#include "sim/volume/volume_term.h"
#include "volume_outcome.h"

namespace {

using wobble::Simulation;

using Outcome = wobble::testing::VolumeOutcome;

Outcome outcome(const wobble::SpringNetwork& rest, const Simulation& simulation) {
  return wobble::testing::volume_outcome(rest, simulation.positions());
}

// The shipped jelly (its base pinned), with the term at its scene's stiffness or off.
std::unique_ptr<Simulation> jelly(const std::string& solver, bool volume,
                                  wobble::SpringNetwork& rest,
                                  std::vector<wobble::Collider> colliders = {}) {
  wobble::Scene scene = wobble::make_builtin_scene("jelly");
  if (!volume) wobble::set_setting_value(scene.params, "volume", 0.0);
  scene.params.solver = solver;
  scene.params.contact.colliders = std::move(colliders);
  rest = scene.network;
  return std::make_unique<Simulation>(scene.network, scene.pins, scene.params,
                                      scene.initial_velocity);
}

void run(Simulation& simulation, double seconds) {
  const int steps = static_cast<int>(seconds / simulation.params().dt + 0.5);
  for (int step = 0; step < steps; ++step)
    ASSERT_EQ(simulation.step(), wobble::StepStatus::ok) << "step " << step;
}

// --drag V:DX,DY,DZ@F-L as the command line scripts it: the vertex is taken hold of, its pin
// target moved by `by` over `seconds`, held for `hold` s, and let go.
void drag(Simulation& simulation, int vertex, const Eigen::Vector3d& by, double seconds,
          double hold) {
  const double dt = simulation.params().dt;
  const Eigen::Vector3d start = simulation.positions().row(vertex).transpose();
  simulation.pin(vertex);
  const int steps = static_cast<int>(seconds / dt + 0.5);
  for (int step = 1; step <= steps; ++step) {
    simulation.set_pin_target(vertex, start + by * (double(step) / steps));
    ASSERT_EQ(simulation.step(), wobble::StepStatus::ok);
  }
  run(simulation, hold);
  simulation.unpin(vertex);
}

// Vertex (i, j, k) of the jelly block of resolution 8 (jelly_block.h).
int jelly_vertex(int i, int j, int k) {
  return (j * 9 + k) * 9 + i;
}

// The issue's drag: the top face's middle dragged sideways, after the jelly settled for 4 s.
Outcome sideways_drag(const std::string& solver, bool volume) {
  wobble::SpringNetwork rest;
  auto simulation = jelly(solver, volume, rest);
  run(*simulation, 4.0);
  drag(*simulation, jelly_vertex(4, 8, 4), Eigen::Vector3d(0.3, 0.0, 0.0), 0.4, 0.5);
  run(*simulation, 2.0);
  return outcome(rest, *simulation);
}

// A top corner pulled down through the bottom face.
Outcome through_the_bottom(const std::string& solver, bool volume) {
  wobble::SpringNetwork rest;
  auto simulation = jelly(solver, volume, rest);
  run(*simulation, 1.0);
  drag(*simulation, jelly_vertex(4, 8, 4), Eigen::Vector3d(0.0, -0.7, 0.0), 0.5, 0.5);
  run(*simulation, 2.0);
  return outcome(rest, *simulation);
}

// The whole block squashed flat by a box lowered onto it, then lifted away.
Outcome squashed_flat(const std::string& solver, bool volume) {
  wobble::Collider box;
  box.type = wobble::ColliderType::box;
  box.size = Eigen::Vector3d(2.0, 0.5, 2.0);
  box.center = Eigen::Vector3d(0.0, 0.5 + 0.25 + 0.05, 0.0);
  wobble::SpringNetwork rest;
  auto simulation = jelly(solver, volume, rest, {box});
  const double dt = simulation->params().dt;
  // Down to 2 cm above the ground over 1 s, held 0.5 s, then out of reach at once.
  const int down = static_cast<int>(1.0 / dt + 0.5);
  for (int step = 0; step < down; ++step) {
    simulation->term<wobble::ColliderContactTerm>()->translate(
        0, Eigen::Vector3d(0.0, -(0.5 + 0.05 - 0.02) / down, 0.0));
    EXPECT_EQ(simulation->step(), wobble::StepStatus::ok);
  }
  run(*simulation, 0.5);
  simulation->term<wobble::ColliderContactTerm>()->translate(0, Eigen::Vector3d(0.0, 10.0, 0.0));
  run(*simulation, 2.0);
  return outcome(rest, *simulation);
}

class VolumeTerm : public ::testing::TestWithParam<std::string> {};

void expect_back(const char* name, Outcome (*scenario)(const std::string&, bool),
                 const std::string& solver) {
  wobble::testing::expect_comes_back(name, solver, scenario(solver, true), scenario(solver, false));
}

TEST_P(VolumeTerm, TheIssuesDragComesBack) {
  expect_back("sideways drag", sideways_drag, GetParam());
}

TEST_P(VolumeTerm, AVertexPulledThroughTheBottomComesBack) {
  expect_back("through the bottom", through_the_bottom, GetParam());
}

TEST_P(VolumeTerm, ABlockSquashedFlatComesBack) {
  expect_back("squashed flat", squashed_flat, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Solvers, VolumeTerm, ::testing::Values("local-global", "lbfgs"));

TEST(NearestRotation, AnInvertedDeformationGetsARightHandedRotation) {
  // A reflection through the x = 0 plane, slightly turned and stretched.
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  const Eigen::Matrix3d F =
      turn * Eigen::Vector3d(-0.5, 1.2, 0.9).asDiagonal() * Eigen::Matrix3d::Identity();
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  const Eigen::Matrix3d R = wobble::nearest_rotation(F, q);
  EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
  // The SVD's answer: U diag(1, 1, det UVᵀ) Vᵀ.
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  D(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant();
  EXPECT_LE((R - svd.matrixU() * D * svd.matrixV().transpose()).norm(), 1e-9);
}

TEST(NearestRotation, StopsOnceTheNextTurnWouldBeBelowTheTolerance) {
  // Deformations from nearly a rotation to far from one (det F down to a few hundredths), each
  // from a warm start off its answer by 1e-1 to 1e-5 rad, as L-BFGS's evaluations start: with
  // the tolerance 1e-7 the answer is within 1e-7 rad of the SVD's.
  srand(11);
  double worst = 0.0;
  int updates = 0, tried = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const double stretch = 0.05 + 0.15 * (trial % 10);
    const Eigen::Matrix3d S =
        Eigen::Matrix3d::Identity() + 0.5 * stretch * Eigen::Matrix3d::Random();
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(3.0 * (trial % 7) / 7.0, Eigen::Vector3d::Random().normalized()).matrix();
    const Eigen::Matrix3d F = turn * S;
    if (F.determinant() < 0.02) continue;
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::Matrix3d exact = svd.matrixU() * svd.matrixV().transpose();
    const double off = std::pow(10.0, -1.0 - (trial % 5));
    const Eigen::Quaterniond start(
        exact * Eigen::AngleAxisd(off, Eigen::Vector3d::Random().normalized()).matrix());
    Eigen::Quaterniond q = start;
    const Eigen::Matrix3d R = wobble::nearest_rotation(F, q, 20, 1e-7);
    worst = std::max(worst, Eigen::AngleAxisd(Eigen::Matrix3d(R.transpose() * exact)).angle());
    // The updates it took: the fewest that give the same answer.
    for (int most = 1; most <= 20; ++most) {
      Eigen::Quaterniond fewer = start;
      if (wobble::nearest_rotation(F, fewer, most, 1e-7) == R) {
        updates += most;
        break;
      }
    }
    ++tried;
  }
  std::printf("[ info ] worst %.2e rad from the SVD's rotation; %.2f updates a rotation\n", worst,
              static_cast<double>(updates) / tried);
  EXPECT_LE(worst, 1e-7);
}

TEST(VolumeTermEnergy, GradientMatchesFiniteDifferences) {
  wobble::JellyBlockOptions options;
  options.resolution = 2;
  const wobble::SpringNetwork rest = wobble::make_jelly_block(options);
  wobble::VolumeTerm term(rest.V, rest.T, 1e4);
  // A deformed pose with some tetrahedra inverted: the top layer pushed below the middle.
  Eigen::MatrixXd p = rest.V;
  srand(3);
  p += 0.05 * Eigen::MatrixXd::Random(p.rows(), 3);
  for (Eigen::Index i = 0; i < p.rows(); ++i) {
    if (rest.V(i, 1) > 0.4) p(i, 1) = 0.1;
  }
  std::vector<char> pinned(p.rows(), 0);
  const wobble::StepContext context{rest, p, p, pinned, 1.0 / 60.0, 0.0};
  Eigen::MatrixXd gradient = Eigen::MatrixXd::Zero(p.rows(), 3);
  term.add_energy(context, p, &gradient);
  const double h = 1e-6;
  double worst = 0.0;
  for (Eigen::Index i = 0; i < p.rows(); ++i) {
    for (int c = 0; c < 3; ++c) {
      Eigen::MatrixXd plus = p, minus = p;
      plus(i, c) += h;
      minus(i, c) -= h;
      const double numeric =
          (term.add_energy(context, plus, nullptr) - term.add_energy(context, minus, nullptr)) /
          (2.0 * h);
      worst = std::max(worst, std::abs(numeric - gradient(i, c)));
    }
  }
  EXPECT_LE(worst, 1e-5 * gradient.cwiseAbs().maxCoeff());
  // And the local-global form agrees: K p − (its pull) is the same gradient, to the rounding of
  // the pull, which the local-global iterations take in single precision (tet_rotations.h).
  std::vector<Eigen::Triplet<double>> triplets;
  term.add_matrix(triplets);
  Eigen::SparseMatrix<double> K(p.rows(), p.rows());
  K.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::MatrixXd pull = Eigen::MatrixXd::Zero(p.rows(), 3);
  term.add_targets(context, p, pull, nullptr);
  EXPECT_LE((K * p - pull - gradient).norm(), 1e-6 * pull.norm());
}

}  // namespace

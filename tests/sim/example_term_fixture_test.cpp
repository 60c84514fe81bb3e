// Examples of adding a term to the step, each in this one file and registered with one line:
// a force (a uniform push), and a term inside the solve (a tether drawing each vertex toward a
// point, with its weight on Q's diagonal, its targets, its energy and a figure of its own).
// Nothing in Simulation or the solvers changes; the tests show that both solvers honour them.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "sim/shapes/cloth_grid.h"
#include "sim/simulation.h"
#include "sim/terms/term_registry.h"

namespace {

// The push a Simulation made now gets (N per vertex); zero, the usual case, leaves it off, so
// the other tests in this program never see it. A real term reads its settings from params.
Eigen::Vector3d push_to_make = Eigen::Vector3d::Zero();

class UniformPush : public wobble::StepTerm {
 public:
  explicit UniformPush(const Eigen::Vector3d& push) : push_(push.transpose()) {}
  const char* name() const override { return "uniform push"; }
  void add_forces(const wobble::StepContext& /*step*/, Eigen::MatrixXd& fext) override {
    fext.rowwise() += push_;
  }

 private:
  Eigen::RowVector3d push_;
};

std::unique_ptr<wobble::StepTerm> make_uniform_push(const wobble::TermSetup& /*setup*/) {
  if (push_to_make.isZero()) return nullptr;
  return std::make_unique<UniformPush>(push_to_make);
}

const wobble::TermRegistration uniform_push{"uniform push", make_uniform_push};

// The tether's stiffness per vertex a Simulation made now gets (N/m); 0 leaves it off.
double tether_to_make = 0.0;

// (κ/2)‖pᵢ − a‖² for every vertex, a the anchor: κ on Q's diagonal, κa into the right-hand side.
class Tether : public wobble::StepTerm {
 public:
  Tether(double stiffness, const Eigen::Vector3d& anchor)
      : stiffness_(stiffness), anchor_(anchor.transpose()) {}
  const char* name() const override { return "tether"; }
  void add_diagonal(const wobble::StepContext& /*step*/, Eigen::VectorXd& diagonal) override {
    diagonal.array() += stiffness_;
  }
  void add_targets(const wobble::StepContext& /*step*/, const Eigen::MatrixXd& p,
                   Eigen::MatrixXd& rhs, double* energy) override {
    rhs.rowwise() += stiffness_ * anchor_;
    if (energy) *energy += add_energy_at(p, nullptr);
  }
  double add_energy(const wobble::StepContext& /*step*/, const Eigen::MatrixXd& p,
                    Eigen::MatrixXd* gradient) const override {
    return add_energy_at(p, gradient);
  }
  wobble::TermStep begin_step(const wobble::StepContext& /*step*/,
                              const Eigen::MatrixXd& /*first*/) override {
    ++steps_;
    wobble::TermStep begun;
    begun.in_solve = true;  // its weights on Q's diagonal never change
    return begun;
  }
  void report(std::vector<wobble::TermFigure>& figures) const override {
    figures.push_back(wobble::TermFigure{"tether", "steps", "", static_cast<double>(steps_)});
  }

 private:
  double add_energy_at(const Eigen::MatrixXd& p, Eigen::MatrixXd* gradient) const {
    const Eigen::MatrixXd off = p.rowwise() - anchor_;
    if (gradient) *gradient += stiffness_ * off;
    return 0.5 * stiffness_ * off.squaredNorm();
  }
  double stiffness_;
  Eigen::RowVector3d anchor_;
  int steps_ = 0;
};

std::unique_ptr<wobble::StepTerm> make_tether(const wobble::TermSetup& /*setup*/) {
  if (tether_to_make == 0.0) return nullptr;
  return std::make_unique<Tether>(tether_to_make, Eigen::Vector3d::Zero());
}

const wobble::TermRegistration tether{"tether", make_tether};

TEST(ExampleTerm, FreeParticleAcceleratesByForceOverMass) {
  // One vertex, no springs, no gravity, at rest: only the push moves it.
  wobble::SpringNetwork particle;
  particle.V = Eigen::RowVector3d(0.1, 0.2, 0.3);
  particle.E.resize(0, 2);
  particle.m = Eigen::VectorXd::Constant(1, 0.5);  // kg
  wobble::SimulationParams params;
  params.gravity.setZero();
  params.dt = 1.0 / 60.0;
  const Eigen::Vector3d force(0.3, 0.0, -0.2);  // N
  push_to_make = force;
  wobble::Simulation simulation(particle, {}, params);
  push_to_make.setZero();

  // Each step solves M(p − 2pᵗ + pᵗ⁻ᐞᵗ)/Δt² = F exactly, so from rest after n steps
  //   p = p₀ + (F/m) Δt² n(n + 1)/2,
  // the discrete ½at². 1e-12 m: 60 steps of double-precision rounding on positions of 0.3 m.
  const int steps = 60;
  for (int n = 0; n < steps; ++n)
    ASSERT_EQ(simulation.step(), wobble::StepStatus::ok);
  const Eigen::RowVector3d expected = particle.V.row(0) + (force.transpose() / 0.5) * params.dt *
                                                              params.dt * steps * (steps + 1) / 2.0;
  EXPECT_LT((simulation.positions().row(0) - expected).norm(), 1e-12);
  // It moved: 0.37 m along the push.
  EXPECT_GT((simulation.positions().row(0) - particle.V.row(0)).norm(), 0.36);
}

// A cloth hanging in gravity, tethered to the origin (κ per vertex): where it comes to rest
// after many steps, for either solver.
Eigen::MatrixXd tethered_rest(const std::string& solver, double stiffness, int* figure_steps) {
  wobble::ClothGridOptions options;
  options.resolution = 6;
  wobble::SpringNetwork cloth = wobble::make_cloth_grid(options);
  cloth.V.col(1).array() += 0.5;
  wobble::SimulationParams params;
  params.solver = solver;
  params.damping = 5.0;
  params.iterations = 30;
  tether_to_make = stiffness;
  wobble::Simulation simulation(cloth, {}, params);
  tether_to_make = 0.0;
  for (int n = 0; n < 600; ++n) {
    if (simulation.step() != wobble::StepStatus::ok) break;
  }
  if (figure_steps)
    *figure_steps = static_cast<int>(simulation.last_step_timing().figure("tether", "steps"));
  return simulation.positions();
}

TEST(ExampleTerm, BothSolversHonourATermInsideTheSolve) {
  // Without the tether the cloth falls freely (its centre 1/2 g t² below where it started);
  // with it, the whole cloth hangs around the anchor, its centre where the tether's pull on
  // the total mass balances gravity: ȳ = −g·m/κ per vertex (the springs' forces sum to zero).
  wobble::ClothGridOptions options;
  options.resolution = 6;
  const wobble::SpringNetwork cloth = wobble::make_cloth_grid(options);
  const double stiffness = 2.0;  // N/m per vertex
  const double mass = cloth.m.mean();
  const double expected_y = -9.81 * mass / stiffness;
  for (const std::string solver : {"local-global", "lbfgs"}) {
    int steps = 0;
    const Eigen::MatrixXd tethered = tethered_rest(solver, stiffness, &steps);
    const Eigen::MatrixXd free = tethered_rest(solver, 0.0, nullptr);
    EXPECT_NEAR(tethered.col(1).mean(), expected_y, 0.02 * std::abs(expected_y)) << solver;
    // 10 s of a fall damped at 5 /s (terminal speed g/c ≈ 2 m/s): about 19 m.
    EXPECT_LT(free.col(1).mean(), -10.0) << solver;
    // Its own figure reaches the step's report by name.
    EXPECT_EQ(steps, 600) << solver;
  }
}

}  // namespace

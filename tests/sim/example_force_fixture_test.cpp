// An example of adding a force: a uniform push on every vertex, in this one file, registered with
// one line. Nothing in Simulation changes; the test shows the stepper applies it.
#include <gtest/gtest.h>

#include <memory>

#include "sim/forces/force_registry.h"
#include "sim/simulation.h"

namespace {

// The push a Simulation made now gets (N per vertex); zero, the usual case, leaves it off, so
// the other tests in this program never see it. A real force reads its settings from params.
Eigen::Vector3d push_to_make = Eigen::Vector3d::Zero();

class UniformPush : public wobble::ForceTerm {
 public:
  explicit UniformPush(const Eigen::Vector3d& push) : push_(push.transpose()) {}
  void apply_forces(const wobble::StepContext& /*step*/, Eigen::MatrixXd& fext) const override {
    fext.rowwise() += push_;
  }

 private:
  Eigen::RowVector3d push_;
};

std::unique_ptr<wobble::ForceTerm> make_uniform_push(const wobble::ForceSetup& /*setup*/) {
  if (push_to_make.isZero()) return nullptr;
  return std::make_unique<UniformPush>(push_to_make);
}

const wobble::ForceRegistration uniform_push{"uniform push", make_uniform_push};

TEST(ExampleForce, FreeParticleAcceleratesByForceOverMass) {
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

}  // namespace

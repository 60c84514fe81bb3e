// The rollback banner's advice fits the cause.
#include "app/viewer/step_advice.h"

#include <gtest/gtest.h>

#include "sim/shapes/builtin_scenes.h"

namespace {

using wobble::FailedStep;

bool says(const FailedStep& failed, const std::string& words) {
  return wobble::describe_failed_step(failed).find(words) != std::string::npos;
}

TEST(StepAdvice, FitsTheCause) {
  FailedStep failed;
  failed.status = wobble::StepStatus::jumped;
  failed.step = 12;
  failed.stiffness_ratio = 10.0;
  EXPECT_TRUE(says(failed, "Paused at step 12: a vertex moved more than 100 times"));
  EXPECT_TRUE(says(failed, "try a smaller dt or more iterations"));

  FailedStep first = failed;
  first.step = 1;
  first.initial_velocity = true;
  EXPECT_TRUE(says(first, "initial velocity"));
  EXPECT_FALSE(says(first, "try a smaller dt or more iterations"));
  first.step = 2;  // after the first step the initial velocity is not the likely cause
  EXPECT_FALSE(says(first, "initial velocity"));

  FailedStep dragged = failed;
  dragged.dragging = true;
  EXPECT_TRUE(says(dragged, "drag more slowly"));

  FailedStep stiff = failed;
  stiff.status = wobble::StepStatus::not_finite;
  stiff.stiffness_ratio = 2.5e4;
  EXPECT_TRUE(says(stiff, "non-finite"));
  EXPECT_TRUE(says(stiff, "k dt^2/m = 2.5e+04"));
}

TEST(StepAdvice, StiffnessRatioOfTheCloth) {
  const wobble::Scene cloth = wobble::make_builtin_scene("cloth");
  wobble::Simulation simulation(cloth.network, cloth.pins, cloth.params);
  const double lightest = cloth.network.m.minCoeff();
  EXPECT_NEAR(wobble::stiffness_ratio(simulation),
              cloth.params.k * cloth.params.dt * cloth.params.dt / lightest, 1e-12);
  simulation.apply(wobble::with_setting(simulation.params(), "k", 1e6));
  EXPECT_GT(wobble::stiffness_ratio(simulation), 1e3) << "the issue's stiff cloth counts as stiff";
}

}  // namespace

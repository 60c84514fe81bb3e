// --compare's settings: what they parse to, what they refuse, and the right side they make.
#include "app/cli/compare_settings.h"

#include <gtest/gtest.h>

#include "sim/input_error.h"

namespace {

using wobble::CompareSettings;
using wobble::parse_compare_settings;

TEST(CompareSettings, ParsesEachSettingSeparatedByCommasOrSpaces) {
  const CompareSettings settings =
      parse_compare_settings("iterations=5, chebyshev=on dt=0.01,k=2e4");
  EXPECT_EQ(settings.number("iterations"), 5);
  EXPECT_EQ(settings.toggle("chebyshev"), true);
  EXPECT_DOUBLE_EQ(*settings.number("dt"), 0.01);
  EXPECT_DOUBLE_EQ(*settings.number("k"), 2e4);
  EXPECT_EQ(parse_compare_settings("chebyshev=off").toggle("chebyshev"), false);
  EXPECT_FALSE(parse_compare_settings("k=10").number("iterations").has_value());
}

TEST(CompareSettings, ParsesTheSolverForTheRightSide) {
  const CompareSettings settings = parse_compare_settings("solver=lbfgs");
  EXPECT_EQ(settings.choice("solver"), "lbfgs");
  EXPECT_TRUE(settings.left.empty());
  wobble::SimulationParams left;
  left.chebyshev = true;
  const wobble::SimulationParams right = settings.applied_to(left);
  EXPECT_EQ(right.solver, "lbfgs");
  EXPECT_EQ(left.solver, "local-global");
  EXPECT_TRUE(right.chebyshev) << "only what it names changes";
}

// A setting named twice gives both sides theirs, read as the sides stand: left, then right.
TEST(CompareSettings, ASettingNamedTwiceSetsTheLeftSideFirst) {
  const CompareSettings settings =
      parse_compare_settings("solver=local-global,solver=lbfgs iterations=8");
  EXPECT_EQ(settings.left.choice("solver"), "local-global");
  EXPECT_EQ(settings.choice("solver"), "lbfgs");
  EXPECT_EQ(settings.number("iterations"), 8);
  EXPECT_FALSE(settings.left.number("iterations").has_value())
      << "named once: the right side's only";
  const CompareSettings both = parse_compare_settings(
      "k=100,dt=0.01,k=900,chebyshev=on,"
      "chebyshev=off,iterations=3,iterations=30");
  EXPECT_EQ(both.left.number("k"), 100.0);
  EXPECT_EQ(both.number("k"), 900.0);
  EXPECT_EQ(both.left.toggle("chebyshev"), true);
  EXPECT_EQ(both.toggle("chebyshev"), false);
  EXPECT_EQ(both.left.number("iterations"), 3);
  EXPECT_EQ(both.number("iterations"), 30);
  EXPECT_FALSE(both.left.number("dt").has_value());
  EXPECT_EQ(both.number("dt"), 0.01);
  wobble::SimulationParams scene;
  scene.solver = "lbfgs";
  EXPECT_EQ(settings.left.applied_to(scene).solver, "local-global");
  EXPECT_EQ(settings.applied_to(scene).solver, "lbfgs");
}

TEST(CompareSettings, AppliesOnlyWhatItNames) {
  wobble::SimulationParams left;
  left.iterations = 50;
  left.k = 400.0;
  left.damping = 0.5;
  const wobble::SimulationParams right = parse_compare_settings("iterations=5").applied_to(left);
  EXPECT_EQ(right.iterations, 5);
  EXPECT_EQ(right.k, 400.0);
  EXPECT_EQ(right.damping, 0.5);
  EXPECT_EQ(right.chebyshev, left.chebyshev);
}

TEST(CompareSettings, RefusesWithTheSettingNamed) {
  const auto message = [](const std::string& text) {
    try {
      parse_compare_settings(text);
    } catch (const wobble::InputError& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message("iterations=0").find("--compare: iterations: expected a whole number"),
            std::string::npos);
  EXPECT_NE(message("iterations=5.5").find("iterations"), std::string::npos);
  EXPECT_NE(message("chebyshev=maybe").find("chebyshev: expected on or off"), std::string::npos);
  EXPECT_NE(message("dt=-1").find("--compare: dt: expected"), std::string::npos);
  EXPECT_NE(message("k=nan").find("--compare: k: expected"), std::string::npos);
  EXPECT_NE(message("stiffness=3").find("unknown setting 'stiffness'"), std::string::npos);
  EXPECT_NE(message("iterations").find("expected name=value"), std::string::npos);
  EXPECT_NE(message(" , ").find("expected settings"), std::string::npos);
  EXPECT_EQ(message("solver=newton"),
            "--compare: solver: expected local-global or lbfgs, got 'newton'");
  EXPECT_EQ(message("solver=L-BFGS").find("--compare: solver: expected"), 0u);
  EXPECT_NE(
      message("solver=lbfgs,solver=lbfgs,solver=local-global").find("solver is given three times"),
      std::string::npos);
  EXPECT_NE(message("k=1,k=2,k=3").find("twice (left, then right)"), std::string::npos);
}

TEST(CompareSettings, DefaultRightSideIsATenthOrTenTimesTheIterations) {
  wobble::SimulationParams left;
  left.iterations = 50;
  EXPECT_EQ(wobble::default_compare_settings(left).number("iterations"), 5);
  left.iterations = 3;
  EXPECT_EQ(wobble::default_compare_settings(left).number("iterations"), 30);
}

TEST(CompareSettings, DescribesASideOnTwoLinesOrThreeWithTheSolver) {
  wobble::SimulationParams params;
  params.iterations = 1;
  params.chebyshev = true;
  params.dt = 0.01;
  params.k = 400.0;
  EXPECT_EQ(wobble::describe_side(params), "1 iteration, Chebyshev\ndt 10 ms, k 400 N/m");
  // Once the sides' solvers differ, each corner names its own, on a line of its own.
  EXPECT_EQ(wobble::describe_side(params, true),
            "local-global (Chebyshev)\n1 iteration\ndt 10 ms, k 400 N/m");
  params.iterations = 30;
  params.solver = "lbfgs";
  EXPECT_EQ(wobble::describe_side(params, true), "L-BFGS\n30 iterations\ndt 10 ms, k 400 N/m");
  params.chebyshev = false;
  params.solver = "local-global";
  EXPECT_EQ(wobble::describe_side(params, true),
            "local-global\n30 iterations\ndt 10 ms, k 400 N/m");
}

}  // namespace

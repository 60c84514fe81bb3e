#include "sim/value_limits.h"

#include <gtest/gtest.h>

#include <limits>

#include "sim/input_error.h"
#include "sim/simulation.h"
#include "test_meshes.h"

namespace {

using wobble::limit_text;
namespace limits = wobble::limits;

TEST(ValueLimits, LimitTextIsTheShortestFormThatReadsBack) {
  EXPECT_EQ(limit_text(1e8), "1e8");
  EXPECT_EQ(limit_text(1e-6), "1e-6");
  EXPECT_EQ(limit_text(1e-9), "1e-9");
  EXPECT_EQ(limit_text(0.25), "0.25");
  EXPECT_EQ(limit_text(1000.0), "1000");
  EXPECT_EQ(limit_text(-1000.0), "-1000");
  EXPECT_EQ(limit_text(1e308), "1e308");
  EXPECT_EQ(limit_text(1.0 / 60.0), "0.016666666666666666");
  EXPECT_EQ(limit_text(0.0), "0");
  EXPECT_EQ(limit_text(2.5507601265176645e-11, 3), "2.55e-11");
  EXPECT_EQ(limit_text(1234.5678, 3), "1230");
}

TEST(ValueLimits, RangesIncludeTheirEndsAndRefuseNaN) {
  EXPECT_TRUE(limits::stiffness.contains(1e8));
  EXPECT_FALSE(limits::stiffness.contains(std::nextafter(1e8, 1e9)));
  EXPECT_TRUE(limits::time_step.contains(1e-9));
  EXPECT_FALSE(limits::time_step.contains(0.0));
  EXPECT_FALSE(limits::stiffness.contains(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_FALSE(limits::acceleration.contains(std::numeric_limits<double>::infinity()));
}

TEST(ValueLimits, ExpectedTextSaysPositiveOnlyForPositiveRanges) {
  EXPECT_EQ(wobble::expected_in(limits::stiffness),
            "a positive number within the limits 1e-6 to 1e8 N/m");
  EXPECT_EQ(wobble::expected_in(limits::acceleration),
            "a number within the limits -1000 to 1000 m/s²");
  EXPECT_EQ(wobble::expected_in(limits::scale), "a positive number within the limits 1e-6 to 1e6");
}

TEST(ValueLimits, OutsideLimitsGivesTheRangeFoundAndTheRangeExpected) {
  EXPECT_EQ(wobble::outside_limits(Eigen::ArrayXd::Constant(3, 0.5), limits::vertex_mass, "m"), "");
  Eigen::ArrayXd masses(3);
  masses << 1e-40, 2.0, 3e-12;
  EXPECT_EQ(wobble::outside_limits(masses, limits::vertex_mass, "vertex masses"),
            "vertex masses from 1e-40 to 2 kg, expected each within the limits 1e-9 to 1e6 kg");
  masses(1) = std::numeric_limits<double>::infinity();
  EXPECT_EQ(wobble::outside_limits(masses, limits::vertex_mass, "vertex masses"),
            "non-finite vertex masses, expected each within the limits 1e-9 to 1e6 kg");
}

// The simulation checks the very limits the command line and the scene files check, so the
// panel's setters cannot go where a file may not.
TEST(ValueLimits, TheSimulationRefusesWhatTheLimitsRefuse) {
  const auto mesh = wobble::testing::chain_mesh(2);
  wobble::SimulationParams params;
  wobble::Simulation simulation(mesh.network, mesh.pins, params);
  EXPECT_NO_THROW(
      simulation.apply(wobble::with_setting(simulation.params(), "k", limits::stiffness.high)));
  EXPECT_THROW(simulation.apply(wobble::with_setting(simulation.params(), "k", 1e308)),
               wobble::InputError);
  EXPECT_NO_THROW(
      simulation.apply(wobble::with_setting(simulation.params(), "dt", limits::time_step.high)));
  EXPECT_THROW(simulation.apply(wobble::with_setting(simulation.params(), "dt", 1e300)),
               wobble::InputError);
  EXPECT_THROW(simulation.apply(wobble::with_setting(simulation.params(), "dt", 1e-300)),
               wobble::InputError);
  EXPECT_THROW(
      simulation.apply(wobble::with_setting(simulation.params(), "iterations",
                                            static_cast<double>(limits::max_iterations + 1))),
      wobble::InputError);
  EXPECT_THROW(
      simulation.apply(wobble::with_setting(
          wobble::with_setting(simulation.params(), "gravity", Eigen::Vector3d(0, -1e300, 0)),
          "gravity-model", std::string("acceleration"))),
      wobble::InputError);
  try {
    simulation.apply(wobble::with_setting(simulation.params(), "k", 1e308));
  } catch (const wobble::InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "k: expected a positive number within the limits 1e-6 to 1e8 N/m, got 1e308");
  }
}

}  // namespace

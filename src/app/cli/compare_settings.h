#ifndef WOBBLE_APP_CLI_COMPARE_SETTINGS_H
#define WOBBLE_APP_CLI_COMPARE_SETTINGS_H

#include <optional>
#include <string>

#include "sim/simulation.h"

namespace wobble {

// What the right side of the split view changes from the left: the settings a class compares.
struct CompareSettings {
  std::optional<int> iterations;
  std::optional<bool> chebyshev;
  std::optional<double> dt;  // s
  std::optional<double> k;   // N/m

  // `params` with these settings in place of its own.
  SimulationParams applied_to(SimulationParams params) const;
};

// Parses --compare's value: settings separated by commas or spaces, each `name=value` with
// name iterations (1 to Simulation::max_iterations), chebyshev (on/off, true/false, 1/0), dt or
// k (within sim/value_limits.h). Throws InputError naming --compare, the setting and what was
// expected.
CompareSettings parse_compare_settings(const std::string& text);

// The settings that tell one side from the other, for its corner, on two lines:
// "50 iterations, plain\ndt 16.7 ms, k 400 N/m".
std::string describe_side(const SimulationParams& params);

// The right side a split view opens with when nothing asked for one: a tenth of the iterations
// (5 against 50, the classic lesson), or ten times as many when there are fewer than ten.
CompareSettings default_compare_settings(const SimulationParams& left);

}  // namespace wobble

#endif

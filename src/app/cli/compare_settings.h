#ifndef WOBBLE_APP_CLI_COMPARE_SETTINGS_H
#define WOBBLE_APP_CLI_COMPARE_SETTINGS_H

#include <optional>
#include <string>

#include "app/cli/settings_overrides.h"
#include "sim/simulation.h"

namespace wobble {

// What the right side of the split view changes from the left (its own settings, inherited),
// and what --compare set on the left side: a setting named twice gives the left side its first
// value and the right side its second ("solver=local-global,solver=lbfgs").
struct CompareSettings : SettingsOverrides {
  SettingsOverrides left;
};

// Parses --compare's value: settings separated by commas or spaces, each `name=value` with
// name iterations (1 to Simulation::max_iterations), solver (local-global or lbfgs), chebyshev
// (on/off, true/false, 1/0), dt or k (within sim/value_limits.h), or an added setting's name
// (within its range; SettingsOverrides::set reads them all). A setting named once is the
// right side's; named twice, the first is the left side's and the second the right side's.
// Throws InputError naming --compare, the setting and what was expected.
CompareSettings parse_compare_settings(const std::string& text);

// The settings that tell one side from the other, for its corner, on two lines:
// "50 iterations, plain\ndt 16.7 ms, k 400 N/m"; with `name_solver` (the sides' solvers differ,
// or one is not the default), on three, the solver first in place of plain or Chebyshev:
// "local-global (Chebyshev)\n50 iterations\ndt 16.7 ms, k 400 N/m", "L-BFGS\n50 iterations\n...".
std::string describe_side(const SimulationParams& params, bool name_solver = false);

// The right side a split view opens with when nothing asked for one: a tenth of the iterations
// (5 against 50, the classic lesson), or ten times as many when there are fewer than ten.
CompareSettings default_compare_settings(const SimulationParams& left);

}  // namespace wobble

#endif

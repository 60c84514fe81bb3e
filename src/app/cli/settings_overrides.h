#ifndef WOBBLE_APP_CLI_SETTINGS_OVERRIDES_H
#define WOBBLE_APP_CLI_SETTINGS_OVERRIDES_H

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sim/simulation_params.h"

namespace wobble {

// Changes to a simulation's settings value (SimulationParams), each given or not: what the
// command line asks of a scene, and what --compare asks of either side of the split view. The
// same names everywhere: k, dt, iterations, solver, chebyshev, and every added setting
// (sim/settings/setting_registry.h) by its name.
struct SettingsOverrides {
  std::optional<double> k;   // N/m
  std::optional<double> dt;  // s
  std::optional<int> iterations;
  std::optional<std::string> solver;  // a registered solver's name (app/cli/solver_choice.h)
  std::optional<bool> chebyshev;
  std::map<std::string, double> added;  // added settings by name, each within its range

  bool empty() const { return !k && !dt && !iterations && !solver && !chebyshev && added.empty(); }
  // `params` with these settings in place of its own.
  SimulationParams applied_to(SimulationParams params) const;
  // Whether `name` (a name of overridable_setting_names) is given.
  bool has(const std::string& name) const;
  // Gives `name` the value `from` has for it, or none when `from` has none.
  void take(const SettingsOverrides& from, const std::string& name);
  // Reads `text` as the value of the setting `name`, checked against its limits. Throws
  // InputError "WHERE: NAME: expected ..., got 'TEXT'" for a bad value, and "WHERE: unknown
  // setting 'NAME' (expected ...)" for a name that is no setting.
  void set(const std::string& name, const std::string& text, const std::string& where);
};

// The names SettingsOverrides takes: iterations, solver, chebyshev, dt, k, then every added
// setting's, in order of registration.
std::vector<std::string> overridable_setting_names();

}  // namespace wobble

#endif

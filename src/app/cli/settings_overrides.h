#ifndef WOBBLE_APP_CLI_SETTINGS_OVERRIDES_H
#define WOBBLE_APP_CLI_SETTINGS_OVERRIDES_H

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sim/settings/setting_registry.h"
#include "sim/settings/simulation_params.h"

namespace wobble {

// Changes to a simulation's settings value (SimulationParams), each given or not: what the
// command line asks of a scene, and what --compare asks of either side of the split view. Kept
// by the settings' names (sim/settings/setting_registry.h), each of its setting's type and
// within its limits.
struct SettingsOverrides {
  std::map<std::string, SettingValue> values;

  bool empty() const { return values.empty(); }
  // `params` with these settings given as a user gives them (all, or those the two sides of the
  // split view share): a switch turned on as turn_on does (the wind over a calm scene blows the
  // breeze), and the switch a given setting implies turned on unless it is given too
  // (--self-collision-thickness: self-collision; --volume-stiffness: the volume term).
  enum Which { every_setting, shared_only };
  SimulationParams applied_to(SimulationParams params, Which which = every_setting) const;
  // Whether `name` is given.
  bool has(const std::string& name) const { return values.count(name) > 0; }
  // The value given for `name`, if any: a number (an integer's too), a switch, a choice's name.
  std::optional<double> number(const std::string& name) const;
  std::optional<bool> toggle(const std::string& name) const;
  std::optional<std::string> choice(const std::string& name) const;
  // Gives `name` the value `from` has for it, or none when `from` has none.
  void take(const SettingsOverrides& from, const std::string& name);
  // Reads `text` as the value of the setting `name`, one of overridable_setting_names, checked
  // against its limits. Throws InputError "WHERE: NAME: expected ..., got 'TEXT'" for a bad
  // value, and "WHERE: unknown setting 'NAME' (expected ...)" for a name that is no setting.
  void set(const std::string& name, const std::string& text, const std::string& where);
};

// The names SettingsOverrides::set takes (--compare's): every setting each side of the split
// view has its own of and the command line gives (k, dt, iterations, solver, chebyshev, then
// every added setting's, in order of registration).
std::vector<std::string> overridable_setting_names();

}  // namespace wobble

#endif

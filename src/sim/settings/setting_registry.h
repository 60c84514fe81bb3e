#ifndef WOBBLE_SIM_SETTINGS_SETTING_REGISTRY_H
#define WOBBLE_SIM_SETTINGS_SETTING_REGISTRY_H

#include <string>
#include <vector>

#include "sim/value_limits.h"

namespace wobble {

struct SimulationParams;

// What a change of a setting costs Simulation::apply.
enum class SettingCost {
  terms,  // the made terms are built again (a term's factory reads the value); no factorization
  refactorize,  // the made terms again, and a numeric re-factorization of Q (a term puts it on
                // Q's diagonal)
};

// A setting added to the simulation beside SimulationParams' own fields, declared once with a
// SettingRegistration in its own file (beside the term that reads it, or in
// sim/registered_terms.cpp). From that declaration alone it reaches:
//   the command line   --NAME VALUE, checked against `range` (app/cli/command_line.h)
//   scene files        "simulation": {"NAME_WITH_UNDERSCORES": VALUE}, read and written
//   --compare          NAME=VALUE, for either side (app/cli/compare_settings.h)
//   the panel          a slider in the Simulation section, for the left and right sides
//   --stats            "settings": {"NAME_WITH_UNDERSCORES": VALUE}
//   Simulation::apply  which does what `cost` says when its value changes
// A term's factory reads it with setting_value(setup.params, "NAME").
struct SettingSpec {
  std::string name;   // lower-case words joined by '-': "tether-stiffness"
  std::string label;  // the panel's: "tether k"
  std::string help;   // one line for --help
  ValueRange range;   // the values it takes, both ends included, and its unit
  double default_value = 0.0;
  SettingCost cost = SettingCost::terms;
  bool log_scale = false;  // the panel's slider moves on a logarithmic scale (range.low > 0)
  // It acts only on a network with tetrahedra (SpringNetwork::T): the panel shows it only there.
  bool solids_only = false;
};

// Registers a setting, as one line at namespace scope of its own file:
//   const SettingRegistration tether_stiffness{{"tether-stiffness", "tether k", "...",
//                                               {1.0, 1e6, "N/m"}, 100.0}};
// Throws std::logic_error (at start-up) for a name already taken, a name that is not lower-case
// words joined by '-', a built-in setting's name, or a default outside the range.
struct SettingRegistration {
  explicit SettingRegistration(const SettingSpec& spec);
};

// Every added setting, in order of registration.
const std::vector<SettingSpec>& added_settings();
// The added setting of that name ("tether-stiffness"), or of that scene key
// ("tether_stiffness"); null when none.
const SettingSpec* find_added_setting(const std::string& name);
// "tether_stiffness": the name as a scene file's and --stats' key.
std::string setting_key(const SettingSpec& spec);

// The value of an added setting in params: the one set, else its default. Throws
// std::out_of_range for a name that is not registered.
double setting_value(const SimulationParams& params, const std::string& name);
// Sets an added setting's value in params. Throws InputError ("NAME: VALUE, expected a number
// within the limits ...", prefixed with `where` and ": " when given) for a value outside its range
// and std::out_of_range for a name that is not registered.
void set_setting_value(SimulationParams& params, const std::string& name, double value,
                       const std::string& where = "");

// Throws InputError unless every value params holds for an added setting is registered and
// within its range (validate_simulation_params calls it).
void validate_added_settings(const SimulationParams& params);

}  // namespace wobble

#endif

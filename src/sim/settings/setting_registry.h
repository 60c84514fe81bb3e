#ifndef WOBBLE_SIM_SETTINGS_SETTING_REGISTRY_H
#define WOBBLE_SIM_SETTINGS_SETTING_REGISTRY_H

#include <Eigen/Core>
#include <functional>
#include <string>
#include <variant>
#include <vector>

#include "sim/value_limits.h"

namespace wobble {

struct SimulationParams;

// Every setting of the simulation is one declaration, a SettingSpec: the built-in ones in
// sim/settings/built_in_settings.cpp (one list, the fields of SimulationParams), and any added
// beside them with a SettingRegistration in a file of its own. Every way a user sets or reads a
// setting is a loop over all_settings():
//   the command line   --NAME VALUE (a switch: --NAME), checked against its range or choices
//                      (app/cli/command_line.h)
//   --compare          NAME=VALUE, for either side (app/cli/compare_settings.h)
//   the page's address ?NAME=VALUE (a switch: ?NAME) (app/web/page_arguments.h)
//   scene files        at its path ("simulation.NAME_WITH_UNDERSCORES" unless it says another:
//                      "material.k", "simulation.wind.drag"), read, written and the only keys
//                      a file's sections take, for those kept there (SettingPlace::in_scene)
//   the panel          a control for the left and right sides, or one in the environment
//                      section for those the sides share (app/viewer/side_settings.h)
//   --stats            "NAME_WITH_UNDERSCORES": VALUE
//   Simulation::apply  which does what `cost` says when its value changes

// What kind of value a setting takes.
enum class SettingType {
  number,   // a real number within `range`
  integer,  // a whole number within `range`
  toggle,   // on or off: a switch (--NAME turns it on; NAME=on|off in --compare)
  choice,   // one of `choices()`, by name
  vector,   // three numbers, each within `range`
};

// A setting's value: a number (an integer's too), a switch, a choice's name, or a vector.
using SettingValue = std::variant<double, bool, std::string, Eigen::Vector3d>;

// What a change of a setting costs Simulation::apply: a set of these, done in the order below
// whichever settings asked for them.
enum class SettingCost : unsigned {
  value = 0,                // read where it is used: nothing to do
  step_work = 1u << 0,      // the work a step would take is checked first (iterations)
  solver = 1u << 1,         // a new step solver is made (and prepared)
  time_step = 1u << 2,      // the previous positions are rescaled, so velocities keep (dt)
  gravity = 1u << 3,        // the gravity forces are computed again
  terms = 1u << 4,          // the terms are made again where the old no longer serve (a term's
                            // factory reads it)
  factorization = 1u << 5,  // a numeric re-factorization of Q
  solver_state = 1u << 6,   // Chebyshev's ρ and L-BFGS's history start again
  refactorize = terms | factorization,  // an added term that puts its value on Q's diagonal
};
constexpr SettingCost operator|(SettingCost a, SettingCost b) {
  return static_cast<SettingCost>(static_cast<unsigned>(a) | static_cast<unsigned>(b));
}
// Whether `costs` holds `cost`.
constexpr bool costs(SettingCost costs, SettingCost cost) {
  return (static_cast<unsigned>(costs) & static_cast<unsigned>(cost)) != 0;
}

// Where a setting reaches the user: a set of these. Every setting reaches Simulation::apply.
enum SettingPlace : unsigned {
  on_command_line = 1u << 0,  // --NAME
  in_address = 1u << 1,       // the page's ?NAME=
  in_panel = 1u << 2,         // a control in the panel (both sides when per_side)
  in_stats = 1u << 3,         // --stats
  in_scene = 1u << 4,         // in a scene file at its scene_path, read and written
  everywhere = on_command_line | in_address | in_panel | in_stats | in_scene,
};

// How the panel shows a setting: its value in a control of its type, a vector as a speed and a
// heading around y (the wind's velocity: "wind (m/s)" and "wind heading"), or a vector as its
// strength along its own direction, which stays (gravity: "gravity (m/s^2)"; a zero vector
// points along number_along).
enum class PanelView { value, speed_and_heading, strength };

// One setting, declared once.
struct SettingSpec {
  std::string name;   // lower-case words joined by '-': "tether-stiffness"
  std::string label;  // the panel's: "tether k"
  std::string help;   // one line for --help
  ValueRange range;   // the values it takes, both ends included, and its unit (number, integer,
                      // each of a vector's numbers)
  double default_value = 0.0;  // a number's; a switch's is 0 or 1 (its field's default otherwise)
  SettingCost cost = SettingCost::terms;
  // The panel's control moves by a factor a pixel (the panel's range, below, starts above 0).
  bool log_scale = false;
  // It acts only on a network with tetrahedra (SpringNetwork::T): the panel shows it only there.
  bool solids_only = false;

  // A number, an integer or a switch for an added setting (its value is kept in
  // SimulationParams::added_settings, a switch's as 0 or 1; default_value 0 or 1); any type for a
  // built-in one.
  SettingType type = SettingType::number;
  // The rest, for built-in settings (an added setting reaches everywhere, on each side).
  unsigned places = everywhere;
  // Each side of the split view has its own (k, dt, ...): --compare sets it and the right side's
  // panel shows it. Otherwise the right side takes the left side's (the environment: gravity,
  // wind, ...).
  bool per_side = true;
  // A course scene may take it: false for what would change the reference's method (Chebyshev,
  // damping, ...), which the command line refuses for one.
  bool course_scene = true;
  std::vector<std::string> (*choices)() = nullptr;  // a choice's names, in order
  // A choice's name as the panel shows it ("L-BFGS" for "lbfgs"); null: the name itself.
  std::string (*choice_label)(const std::string& name) = nullptr;
  // The panel's control: its range when narrower than `range` (panel_range.high > low; in the
  // panel's unit), and a number's printf format.
  ValueRange panel_range{0.0, 0.0, ""};
  const char* panel_format = "%.4g";
  // The panel's label when not `label` ("wind (W)": with its key), and its unit when not
  // range's: the value times panel_scale ("mm" for a thickness in m: 1000).
  const char* panel_label = "";
  const char* panel_unit = "";
  double panel_scale = 1.0;
  PanelView panel_view = PanelView::value;
  // Whether the panel offers it for `params` (friction: with colliders; the wind's speed: for
  // the aerodynamic wind); null: always. And the switch it shows only beside, while that is on
  // (self-collision's thickness: self-collision).
  bool (*offered)(const SimulationParams& params) = nullptr;
  const char* shown_with = "";
  // A switch that applies only with some values of another setting (Chebyshev with the
  // local-global solver): that setting's name, whether it applies to `params`, and why not, which
  // the panel says on the control it greys out.
  const char* applies_with = "";
  bool (*applies)(const SimulationParams& params) = nullptr;
  const char* why_not = "";
  // Where a scene file keeps it (with in_scene): its key's path from the file's top, dotted
  // ("material.k", "simulation.wind.drag"); empty for "simulation.NAME_WITH_UNDERSCORES". A
  // section_switch's path is its section's ("simulation.wind").
  const char* scene_path = "";
  // A switch that is its section being in the file: the section, an object, turns it on by
  // being there (and holds its "on" key when switch_key: the wind's, to keep its settings
  // while off). A file keeps the section while the switch is on, or, with a key, while any of
  // the section's settings differs from its default.
  bool section_switch = false;
  bool switch_key = false;
  // A setting its section cannot do without: a file with the section must give it.
  bool needed_in_section = false;
  // A vector a file may also give as one number, that number times this direction (gravity: a
  // number is the downward acceleration). Zero: three numbers only.
  Eigen::Vector3d number_along = Eigen::Vector3d::Zero();
  // What turning the switch on from the command line, the page's address, the panel or a key
  // does besides (the wind: a calm scene's becomes the default breeze). Null: nothing.
  void (*when_turned_on)(SimulationParams& params) = nullptr;
  // A switch that giving this on the command line, in the page's address or in a scene file
  // turns on too, unless the switch is given there as well (self-collision-thickness:
  // self-collision; volume-stiffness: volume). Empty: none.
  const char* implies = "";
  // The field of SimulationParams it reads and writes (built_in_settings.cpp binds them).
  std::function<SettingValue(const SimulationParams&)> get = nullptr;
  std::function<void(SimulationParams&, const SettingValue&)> set = nullptr;
};

// Registers a setting, as one line at namespace scope of its own file:
//   const SettingRegistration tether_stiffness{{"tether-stiffness", "tether k", "...",
//                                               {1.0, 1e6, "N/m"}, 100.0}};
// Throws std::logic_error (at start-up) for a name already taken, a name that is not lower-case
// words joined by '-', a built-in setting's name, or a default outside the range.
struct SettingRegistration {
  explicit SettingRegistration(const SettingSpec& spec);
};

// Every setting: the built-in ones, then the added ones in order of registration.
const std::vector<SettingSpec>& all_settings();
// The setting of that name ("tether-stiffness"), or of that key ("tether_stiffness"); null
// when none.
const SettingSpec* find_setting(const std::string& name);
// Every added setting, in order of registration.
const std::vector<SettingSpec>& added_settings();
// The added setting of that name ("tether-stiffness"), or of that scene key
// ("tether_stiffness"); null when none.
const SettingSpec* find_added_setting(const std::string& name);
// "tether_stiffness": the name as a scene file's and --stats' key.
std::string setting_key(const SettingSpec& spec);
// Where a scene file keeps the setting, as the keys from the file's top: {"material", "k"},
// {"simulation", "tether_stiffness"}; a section switch's, its section's {"simulation", "wind"}.
std::vector<std::string> scene_path(const SettingSpec& spec);
// `params` with the switch turned on as a user turns it on: its when_turned_on done first.
void turn_on(const SettingSpec& spec, SimulationParams& params);
// The switch turned off, or on as turn_on does (the W key, the wind's checkbox).
void toggle(const SettingSpec& spec, SimulationParams& params);

// The setting's value in params.
SettingValue value_of(const SettingSpec& spec, const SimulationParams& params);
// `params` with the setting `name` given `value` (of its type), unchecked: apply checks.
// Throws std::out_of_range for a name that is no setting.
SimulationParams with_setting(SimulationParams params, const std::string& name,
                              const SettingValue& value);
// Reads `text` as a value of the setting: "expected ..., got 'TEXT'" (an InputError, prefixed
// with `where` and ": " when given) for a value it does not take. A switch reads on/off,
// true/false, 1/0; a vector three numbers separated by commas.
SettingValue read_setting(const SettingSpec& spec, const std::string& text,
                          const std::string& where);
// The value as read_setting reads it back exactly: "0.016666666666666666", "on", "lbfgs",
// "0,-9.81,0".
std::string setting_text(const SettingValue& value);
// A number's (an integer's, a switch's 0 or 1) value as a double; 0 for a choice or a vector.
double setting_number(const SettingValue& value);
// Whether `value` is of the setting's type and within its range or choices.
bool setting_accepts(const SettingSpec& spec, const SettingValue& value);

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

// The built-in settings, in the order the command line's --help lists them.
const std::vector<SettingSpec>& built_in_settings();

}  // namespace wobble

#endif

#include "app/cli/settings_overrides.h"

#include "app/cli/solver_choice.h"
#include "io/parse_number.h"
#include "sim/input_error.h"
#include "sim/settings/setting_registry.h"
#include "sim/simulation.h"
#include "sim/value_limits.h"

namespace wobble {

namespace {

double value_in(const std::string& where, const std::string& name, const std::string& text,
                const ValueRange& range) {
  const std::optional<double> value = parse_number<double>(text);
  if (!value || !range.contains(*value)) {
    throw InputError(where + ": " + name + ": expected " + expected_in(range) + ", got '" + text +
                     "'");
  }
  return *value;
}

}  // namespace

std::vector<std::string> overridable_setting_names() {
  std::vector<std::string> names = {"iterations", "solver", "chebyshev", "dt", "k"};
  for (const SettingSpec& spec : added_settings())
    names.push_back(spec.name);
  return names;
}

SimulationParams SettingsOverrides::applied_to(SimulationParams params) const {
  if (iterations) params.iterations = *iterations;
  if (chebyshev) params.chebyshev = *chebyshev;
  if (solver) params.solver = *solver;
  if (dt) params.dt = *dt;
  if (k) params.k = *k;
  for (const auto& [name, value] : added)
    params.added_settings[name] = value;
  return params;
}

bool SettingsOverrides::has(const std::string& name) const {
  if (name == "iterations") return iterations.has_value();
  if (name == "chebyshev") return chebyshev.has_value();
  if (name == "solver") return solver.has_value();
  if (name == "dt") return dt.has_value();
  if (name == "k") return k.has_value();
  return added.count(name) > 0;
}

void SettingsOverrides::take(const SettingsOverrides& from, const std::string& name) {
  if (name == "iterations") {
    iterations = from.iterations;
  } else if (name == "chebyshev") {
    chebyshev = from.chebyshev;
  } else if (name == "solver") {
    solver = from.solver;
  } else if (name == "dt") {
    dt = from.dt;
  } else if (name == "k") {
    k = from.k;
  } else if (from.added.count(name)) {
    added[name] = from.added.at(name);
  } else {
    added.erase(name);
  }
}

void SettingsOverrides::set(const std::string& name, const std::string& text,
                            const std::string& where) {
  if (name == "iterations") {
    const std::optional<long> count = parse_number<long>(text);
    if (!count || *count < 1 || *count > Simulation::max_iterations) {
      throw InputError(where + ": iterations: expected a whole number from 1 to " +
                       std::to_string(Simulation::max_iterations) + ", got '" + text + "'");
    }
    iterations = static_cast<int>(*count);
  } else if (name == "chebyshev") {
    if (text == "on" || text == "true" || text == "1") {
      chebyshev = true;
    } else if (text == "off" || text == "false" || text == "0") {
      chebyshev = false;
    } else {
      throw InputError(where + ": chebyshev: expected on or off, got '" + text + "'");
    }
  } else if (name == "solver") {
    solver = parse_solver(where + ": solver", text);
  } else if (name == "dt") {
    dt = value_in(where, name, text, limits::time_step);
  } else if (name == "k") {
    k = value_in(where, name, text, limits::stiffness);
  } else if (const SettingSpec* spec = find_added_setting(name); spec && spec->name == name) {
    added[name] = value_in(where, name, text, spec->range);
  } else {
    std::string expected;
    const std::vector<std::string> names = overridable_setting_names();
    for (std::size_t i = 0; i < names.size(); ++i)
      expected += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    throw InputError(where + ": unknown setting '" + name + "' (expected " + expected + ")");
  }
}

}  // namespace wobble

#include "sim/settings/setting_registry.h"

#include <algorithm>
#include <stdexcept>

#include "sim/input_error.h"
#include "sim/simulation_params.h"

namespace wobble {

namespace {

std::vector<SettingSpec>& registry() {
  static std::vector<SettingSpec> settings;
  return settings;
}

// SimulationParams' own settings, by the names the command line and --compare give them.
const char* const built_in_names[] = {
    "k",
    "dt",
    "iterations",
    "solver",
    "chebyshev",
    "damping",
    "friction",
    "wind",
    "gravity",
    "self-collision",
    "self-collision-thickness",
    "threads",
    "frames",
    "scene",
};

bool well_formed(const std::string& name) {
  if (name.empty() || name.front() == '-' || name.back() == '-') return false;
  for (std::size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    const bool letter = c >= 'a' && c <= 'z', digit = c >= '0' && c <= '9';
    if (!letter && !digit && c != '-') return false;
    if (c == '-' && name[i + 1] == '-') return false;
  }
  return name.front() >= 'a' && name.front() <= 'z';
}

}  // namespace

SettingRegistration::SettingRegistration(const SettingSpec& spec) {
  if (!well_formed(spec.name)) {
    throw std::logic_error("setting '" + spec.name + "': expected lower-case words joined by '-'");
  }
  for (const char* taken : built_in_names) {
    if (spec.name == taken) throw std::logic_error("setting '" + spec.name + "': a built-in name");
  }
  if (find_added_setting(spec.name)) {
    throw std::logic_error("setting '" + spec.name + "': registered twice");
  }
  if (!(spec.range.low <= spec.range.high) || !spec.range.contains(spec.default_value) ||
      (spec.log_scale && !(spec.range.low > 0.0))) {
    throw std::logic_error("setting '" + spec.name + "': its default or range is not a range");
  }
  registry().push_back(spec);
}

const std::vector<SettingSpec>& added_settings() {
  return registry();
}

std::string setting_key(const SettingSpec& spec) {
  std::string key = spec.name;
  std::replace(key.begin(), key.end(), '-', '_');
  return key;
}

const SettingSpec* find_added_setting(const std::string& name) {
  for (const SettingSpec& spec : registry()) {
    if (spec.name == name || setting_key(spec) == name) return &spec;
  }
  return nullptr;
}

namespace {

const SettingSpec& registered(const std::string& name) {
  const SettingSpec* spec = find_added_setting(name);
  if (!spec) throw std::out_of_range("no setting is registered as '" + name + "'");
  return *spec;
}

}  // namespace

double setting_value(const SimulationParams& params, const std::string& name) {
  const SettingSpec& spec = registered(name);
  const auto set = params.added_settings.find(spec.name);
  return set != params.added_settings.end() ? set->second : spec.default_value;
}

void set_setting_value(SimulationParams& params, const std::string& name, double value,
                       const std::string& where) {
  const SettingSpec& spec = registered(name);
  if (!spec.range.contains(value)) {
    throw InputError((where.empty() ? "" : where + ": ") + spec.name + ": expected " +
                     expected_in(spec.range) + ", got " + limit_text(value));
  }
  params.added_settings[spec.name] = value;
}

void validate_added_settings(const SimulationParams& params) {
  for (const auto& [name, value] : params.added_settings) {
    const SettingSpec* spec = find_added_setting(name);
    if (!spec || spec->name != name) throw InputError(name + ": no such setting");
    if (!spec->range.contains(value)) {
      throw InputError(name + ": expected " + expected_in(spec->range) + ", got " +
                       limit_text(value));
    }
  }
}

}  // namespace wobble

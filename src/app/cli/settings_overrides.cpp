#include "app/cli/settings_overrides.h"

#include "sim/input_error.h"

namespace wobble {

namespace {

bool overridable(const SettingSpec& spec) {
  return spec.per_side && (spec.places & on_command_line) != 0;
}

}  // namespace

std::vector<std::string> overridable_setting_names() {
  std::vector<std::string> names;
  for (const SettingSpec& spec : all_settings()) {
    if (overridable(spec)) names.push_back(spec.name);
  }
  return names;
}

SimulationParams SettingsOverrides::applied_to(SimulationParams params, Which which) const {
  for (const auto& [name, value] : values) {
    const SettingSpec& spec = *find_setting(name);
    if (which == shared_only && spec.per_side) continue;
    if (spec.type == SettingType::toggle && std::get<bool>(value)) {
      turn_on(spec, params);
    } else {
      spec.set(params, value);
    }
    if (*spec.implies != '\0' && !has(spec.implies)) turn_on(*find_setting(spec.implies), params);
  }
  return params;
}

std::optional<double> SettingsOverrides::number(const std::string& name) const {
  const auto given = values.find(name);
  if (given == values.end()) return std::nullopt;
  return setting_number(given->second);
}

std::optional<bool> SettingsOverrides::toggle(const std::string& name) const {
  const auto given = values.find(name);
  if (given == values.end() || !std::holds_alternative<bool>(given->second)) return std::nullopt;
  return std::get<bool>(given->second);
}

std::optional<std::string> SettingsOverrides::choice(const std::string& name) const {
  const auto given = values.find(name);
  if (given == values.end() || !std::holds_alternative<std::string>(given->second)) {
    return std::nullopt;
  }
  return std::get<std::string>(given->second);
}

void SettingsOverrides::take(const SettingsOverrides& from, const std::string& name) {
  const auto given = from.values.find(name);
  if (given != from.values.end()) {
    values[name] = given->second;
  } else {
    values.erase(name);
  }
}

void SettingsOverrides::set(const std::string& name, const std::string& text,
                            const std::string& where) {
  const SettingSpec* spec = find_setting(name);
  if (!spec || spec->name != name || !overridable(*spec)) {
    std::string expected;
    const std::vector<std::string> names = overridable_setting_names();
    for (std::size_t i = 0; i < names.size(); ++i)
      expected += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    throw InputError(where + ": unknown setting '" + name + "' (expected " + expected + ")");
  }
  values[name] = read_setting(*spec, text, where + ": " + name);
}

}  // namespace wobble

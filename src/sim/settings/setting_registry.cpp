#include "sim/settings/setting_registry.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <optional>
#include <stdexcept>

#include "sim/input_error.h"
#include "sim/parse_number.h"
#include "sim/settings/simulation_params.h"

namespace wobble {

namespace {

std::vector<SettingSpec>& registry() {
  static std::vector<SettingSpec> settings;
  return settings;
}

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

// Names the command line takes for itself beside the settings.
const char* const other_option_names[] = {"threads", "frames", "scene"};

}  // namespace

SettingRegistration::SettingRegistration(const SettingSpec& given) {
  if (!well_formed(given.name)) {
    throw std::logic_error("setting '" + given.name + "': expected lower-case words joined by '-'");
  }
  for (const SettingSpec& taken : built_in_settings()) {
    if (given.name == taken.name)
      throw std::logic_error("setting '" + given.name + "': a built-in name");
  }
  for (const char* taken : other_option_names) {
    if (given.name == taken)
      throw std::logic_error("setting '" + given.name + "': a built-in name");
  }
  if (find_added_setting(given.name)) {
    throw std::logic_error("setting '" + given.name + "': registered twice");
  }
  SettingSpec spec = given;
  if (spec.type == SettingType::toggle) spec.range = ValueRange{0.0, 1.0, ""};
  if (spec.type != SettingType::number && spec.type != SettingType::integer &&
      spec.type != SettingType::toggle) {
    throw std::logic_error("setting '" + given.name +
                           "': expected a number, an integer or a switch");
  }
  const ValueRange& panel_range =
      spec.panel_range.high > spec.panel_range.low ? spec.panel_range : spec.range;
  if (!(spec.range.low <= spec.range.high) || !spec.range.contains(spec.default_value) ||
      (spec.type == SettingType::toggle && spec.default_value != 0.0 &&
       spec.default_value != 1.0) ||
      (spec.log_scale && !(panel_range.low > 0.0))) {
    throw std::logic_error("setting '" + given.name + "': its default or range is not a range");
  }
  // An added setting's value is a number kept by name in SimulationParams::added_settings (a
  // switch's 0 or 1).
  const std::string name = spec.name;
  const bool toggle = spec.type == SettingType::toggle;
  spec.get = [name, toggle](const SimulationParams& params) -> SettingValue {
    const double value = setting_value(params, name);
    if (toggle) return value != 0.0;
    return value;
  };
  spec.set = [name](SimulationParams& params, const SettingValue& value) {
    params.added_settings[name] = setting_number(value);
  };
  registry().push_back(spec);
}

const std::vector<SettingSpec>& added_settings() {
  return registry();
}

const std::vector<SettingSpec>& all_settings() {
  // Registrations only append, all at start-up (static initialization): the list is made again
  // when one came after, so that a call during start-up sees those registered so far. Two
  // threads' first calls are one after the other.
  static std::mutex making;
  static std::vector<SettingSpec> all;
  const std::lock_guard<std::mutex> lock(making);
  const std::vector<SettingSpec>& built_in = built_in_settings();
  if (all.size() != built_in.size() + registry().size()) {
    all = built_in;
    all.insert(all.end(), registry().begin(), registry().end());
  }
  return all;
}

std::string setting_key(const SettingSpec& spec) {
  std::string key = spec.name;
  std::replace(key.begin(), key.end(), '-', '_');
  return key;
}

std::vector<std::string> scene_path(const SettingSpec& spec) {
  if (*spec.scene_path == '\0') return {"simulation", setting_key(spec)};
  std::vector<std::string> keys(1);
  for (const char* c = spec.scene_path; *c != '\0'; ++c) {
    if (*c == '.') {
      keys.emplace_back();
    } else {
      keys.back() += *c;
    }
  }
  return keys;
}

void turn_on(const SettingSpec& spec, SimulationParams& params) {
  if (spec.when_turned_on) spec.when_turned_on(params);
  spec.set(params, true);
}

void toggle(const SettingSpec& spec, SimulationParams& params) {
  if (std::get<bool>(spec.get(params))) {
    spec.set(params, false);
  } else {
    turn_on(spec, params);
  }
}

const SettingSpec* find_added_setting(const std::string& name) {
  for (const SettingSpec& spec : registry()) {
    if (spec.name == name || setting_key(spec) == name) return &spec;
  }
  return nullptr;
}

const SettingSpec* find_setting(const std::string& name) {
  for (const SettingSpec& spec : all_settings()) {
    if (spec.name == name || setting_key(spec) == name) return &spec;
  }
  return nullptr;
}

SettingValue value_of(const SettingSpec& spec, const SimulationParams& params) {
  return spec.get(params);
}

SimulationParams with_setting(SimulationParams params, const std::string& name,
                              const SettingValue& value) {
  const SettingSpec* spec = find_setting(name);
  if (!spec || spec->name != name) throw std::out_of_range("no setting is named '" + name + "'");
  spec->set(params, value);
  return params;
}

double setting_number(const SettingValue& value) {
  if (const double* number = std::get_if<double>(&value)) return *number;
  if (const bool* on = std::get_if<bool>(&value)) return *on ? 1.0 : 0.0;
  return 0.0;
}

namespace {

std::string number_text(double value) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof(text), value);
  return error == std::errc() ? std::string(text, end) : std::string("nan");
}

std::string choices_text(const SettingSpec& spec) {
  const std::vector<std::string> names = spec.choices ? spec.choices() : std::vector<std::string>{};
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i)
    text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return text;
}

}  // namespace

std::string setting_text(const SettingValue& value) {
  if (const double* number = std::get_if<double>(&value)) return number_text(*number);
  if (const bool* on = std::get_if<bool>(&value)) return *on ? "on" : "off";
  if (const std::string* choice = std::get_if<std::string>(&value)) return *choice;
  const Eigen::Vector3d& vector = std::get<Eigen::Vector3d>(value);
  return number_text(vector.x()) + "," + number_text(vector.y()) + "," + number_text(vector.z());
}

bool setting_accepts(const SettingSpec& spec, const SettingValue& value) {
  switch (spec.type) {
    case SettingType::number:
      return std::holds_alternative<double>(value) && spec.range.contains(std::get<double>(value));
    case SettingType::integer: {
      if (!std::holds_alternative<double>(value)) return false;
      const double number = std::get<double>(value);
      return number == std::floor(number) && spec.range.contains(number);
    }
    case SettingType::toggle:
      return std::holds_alternative<bool>(value);
    case SettingType::choice: {
      if (!std::holds_alternative<std::string>(value) || !spec.choices) return false;
      const std::vector<std::string> names = spec.choices();
      return std::find(names.begin(), names.end(), std::get<std::string>(value)) != names.end();
    }
    case SettingType::vector:
      return std::holds_alternative<Eigen::Vector3d>(value) &&
             std::get<Eigen::Vector3d>(value).allFinite() &&
             (std::get<Eigen::Vector3d>(value).array() >= spec.range.low).all() &&
             (std::get<Eigen::Vector3d>(value).array() <= spec.range.high).all();
  }
  return false;
}

SettingValue read_setting(const SettingSpec& spec, const std::string& text,
                          const std::string& where) {
  const std::string prefix = where.empty() ? "" : where + ": ";
  const auto refuse = [&](const std::string& expected) {
    throw InputError(prefix + "expected " + expected + ", got '" + text + "'");
  };
  switch (spec.type) {
    case SettingType::number: {
      const std::optional<double> value = parse_number<double>(text);
      // A setting that must be positive says so first, as the command line always has.
      if (spec.range.low > 0.0 && (!value || !std::isfinite(*value) || !(*value > 0.0)))
        refuse("a positive finite number");
      if (!value || !spec.range.contains(*value)) refuse(expected_in(spec.range));
      return *value;
    }
    case SettingType::integer: {
      const std::optional<long> value = parse_number<long>(text);
      if (!value || !spec.range.contains(static_cast<double>(*value))) {
        refuse("a whole number from " + limit_text(spec.range.low) + " to " +
               limit_text(spec.range.high));
      }
      return static_cast<double>(*value);
    }
    case SettingType::toggle:
      if (text == "on" || text == "true" || text == "1") return true;
      if (text == "off" || text == "false" || text == "0") return false;
      refuse("on or off");
      break;
    case SettingType::choice: {
      SettingValue value = text;
      if (!setting_accepts(spec, value)) refuse(choices_text(spec));
      return value;
    }
    case SettingType::vector: {
      Eigen::Vector3d vector;
      std::size_t start = 0;
      for (int i = 0; i < 3; ++i) {
        const std::size_t comma = i < 2 ? text.find(',', start) : text.size();
        if (comma == std::string::npos) refuse("three numbers X,Y,Z " + within_text(spec.range));
        const std::optional<double> value = parse_number<double>(text.substr(start, comma - start));
        if (!value || !spec.range.contains(*value))
          refuse("three numbers X,Y,Z " + within_text(spec.range));
        vector(i) = *value;
        start = comma + 1;
      }
      return vector;
    }
  }
  refuse("a value");
  return 0.0;
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

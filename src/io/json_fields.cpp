#include "json_fields.h"

#include <cmath>

#include "sim/input_error.h"

namespace wobble {

namespace {

// A short rendering of a JSON value for error messages.
std::string shown(const nlohmann::json& value) {
  std::string text = value.dump();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return text;
}

}  // namespace

JsonFields::JsonFields(const std::string& file, const nlohmann::json& object, std::string path)
    : file_(file), object_(object), path_(std::move(path)) {}

bool JsonFields::has(const std::string& key) const {
  return object_.contains(key);
}

std::string JsonFields::where(const std::string& key) const {
  return file_ + ": " + (path_.empty() ? "" : path_ + ".") + key;
}

void JsonFields::fail(const std::string& key, const std::string& expected) const {
  const auto found = object_.find(key);
  throw InputError(where(key) + ": expected " + expected +
                   (found != object_.end() ? ", got " + shown(*found) : ""));
}

const nlohmann::json& JsonFields::raw(const std::string& key) {
  read_.insert(key);
  return object_.at(key);
}

JsonFields JsonFields::object(const std::string& key) {
  const nlohmann::json& value = raw(key);
  if (!value.is_object()) fail(key, "an object");
  return JsonFields(file_, value, (path_.empty() ? "" : path_ + ".") + key);
}

std::optional<double> JsonFields::number(const std::string& key) {
  if (!has(key)) return std::nullopt;
  const nlohmann::json& value = raw(key);
  if (!value.is_number() || !std::isfinite(value.get<double>())) fail(key, "a number");
  return value.get<double>();
}

std::optional<double> JsonFields::positive(const std::string& key) {
  const std::optional<double> value = number(key);
  if (value && !(*value > 0.0)) fail(key, "a positive number");
  return value;
}

std::optional<double> JsonFields::number_in(const std::string& key, const ValueRange& range) {
  if (!has(key)) return std::nullopt;
  const nlohmann::json& value = raw(key);
  if (!value.is_number() || !range.contains(value.get<double>())) fail(key, expected_in(range));
  return value.get<double>();
}

std::optional<int> JsonFields::whole(const std::string& key, int low, int high) {
  if (!has(key)) return std::nullopt;
  const nlohmann::json& value = raw(key);
  if (!value.is_number_integer() || value.get<long long>() < low || value.get<long long>() > high) {
    fail(key, "a whole number from " + std::to_string(low) + " to " + std::to_string(high));
  }
  return static_cast<int>(value.get<long long>());
}

std::optional<bool> JsonFields::flag(const std::string& key) {
  if (!has(key)) return std::nullopt;
  const nlohmann::json& value = raw(key);
  if (!value.is_boolean()) fail(key, "true or false");
  return value.get<bool>();
}

std::optional<std::string> JsonFields::text(const std::string& key) {
  if (!has(key)) return std::nullopt;
  const nlohmann::json& value = raw(key);
  if (!value.is_string()) fail(key, "a string");
  return value.get<std::string>();
}

std::optional<Eigen::Vector3d> JsonFields::vector3(const std::string& key) {
  if (!has(key)) return std::nullopt;
  const nlohmann::json& value = raw(key);
  const auto finite = [](const nlohmann::json& x) {
    return x.is_number() && std::isfinite(x.get<double>());
  };
  if (!value.is_array() || value.size() != 3 || !finite(value[0]) || !finite(value[1]) ||
      !finite(value[2])) {
    fail(key, "three numbers [x, y, z]");
  }
  return Eigen::Vector3d(value[0].get<double>(), value[1].get<double>(), value[2].get<double>());
}

std::optional<Eigen::Vector3d> JsonFields::vector3_in(const std::string& key,
                                                      const ValueRange& range) {
  if (!has(key)) return std::nullopt;
  const nlohmann::json& value = raw(key);
  const auto in_range = [&](const nlohmann::json& x) {
    return x.is_number() && range.contains(x.get<double>());
  };
  if (!value.is_array() || value.size() != 3 || !in_range(value[0]) || !in_range(value[1]) ||
      !in_range(value[2])) {
    fail(key, "three numbers [x, y, z], each " + within_text(range));
  }
  return Eigen::Vector3d(value[0].get<double>(), value[1].get<double>(), value[2].get<double>());
}

std::optional<Eigen::Vector3d> JsonFields::color(const std::string& key) {
  if (!has(key)) return std::nullopt;
  const nlohmann::json& value = raw(key);
  const auto unit = [](const nlohmann::json& x) {
    return x.is_number() && x.get<double>() >= 0.0 && x.get<double>() <= 1.0;
  };
  if (!value.is_array() || value.size() != 3 || !unit(value[0]) || !unit(value[1]) ||
      !unit(value[2])) {
    fail(key, "a colour [r, g, b] with each in [0, 1]");
  }
  return Eigen::Vector3d(value[0].get<double>(), value[1].get<double>(), value[2].get<double>());
}

std::vector<std::string> JsonFields::unread() const {
  std::vector<std::string> keys;
  for (const auto& item : object_.items()) {
    if (!read_.count(item.key())) keys.push_back((path_.empty() ? "" : path_ + ".") + item.key());
  }
  return keys;
}

}  // namespace wobble

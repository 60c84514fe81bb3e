#include "json_fields.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "sim/input_error.h"
#include "text_pieces.h"

namespace wobble {

namespace {

// Appends `value` to `text` until `text` is longer than `max_chars`.
void append_preview(const nlohmann::json& value, std::size_t max_chars, std::string& text) {
  if (value.is_array() || value.is_object()) {
    text += value.is_array() ? '[' : '{';
    bool first = true;
    for (auto item = value.begin(); item != value.end() && text.size() <= max_chars; ++item) {
      if (!first) text += ',';
      first = false;
      if (value.is_object()) text += nlohmann::json(item.key()).dump() + ':';
      append_preview(*item, max_chars, text);
    }
    text += value.is_array() ? ']' : '}';
  } else {
    text += value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  }
}

}  // namespace

std::string json_preview(const nlohmann::json& value, std::size_t max_chars) {
  std::string text;
  append_preview(value, max_chars, text);
  if (text.size() > max_chars) text = text.substr(0, max_chars - 3) + "...";
  return text;
}

std::optional<long long> whole_number(const nlohmann::json& value, long long low, long long high) {
  if (value.is_number_unsigned()) {
    const auto n = value.get<std::uint64_t>();
    if (high < 0 || n > static_cast<std::uint64_t>(high) ||
        (low > 0 && n < static_cast<std::uint64_t>(low))) {
      return std::nullopt;
    }
    return static_cast<long long>(n);
  }
  if (value.is_number_integer()) {
    const auto n = value.get<std::int64_t>();
    if (n < low || n > high) return std::nullopt;
    return static_cast<long long>(n);
  }
  if (!value.is_number_float()) return std::nullopt;
  // 50.0 or 1e1: a double, whole when it has no fraction. The range is checked on the double,
  // before any conversion, so that 1e300 cannot wrap into range.
  const double x = value.get<double>();
  if (!std::isfinite(x) || x != std::floor(x) || std::abs(x) >= 0x1p62) return std::nullopt;
  if (x < static_cast<double>(low) || x > static_cast<double>(high)) return std::nullopt;
  return static_cast<long long>(x);
}

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
                   (found != object_.end() ? ", got " + json_preview(*found) : ""));
}

void JsonFields::allow_only(const std::vector<std::string>& keys, const std::string& what) const {
  for (const auto& item : object_.items()) {
    if (std::find(keys.begin(), keys.end(), item.key()) == keys.end()) {
      throw InputError(where(item.key()) + ": unknown key, " + what + " takes " +
                       comma_joined(keys));
    }
  }
}

const nlohmann::json& JsonFields::raw(const std::string& key) {
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
  const std::optional<long long> value = whole_number(raw(key), low, high);
  if (!value)
    fail(key, "a whole number from " + std::to_string(low) + " to " + std::to_string(high));
  return static_cast<int>(*value);
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

}  // namespace wobble

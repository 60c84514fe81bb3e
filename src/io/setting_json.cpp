#include "io/setting_json.h"

namespace wobble {

nlohmann::json setting_json(const SettingSpec& spec, const SettingValue& value) {
  if (const bool* on = std::get_if<bool>(&value)) return *on;
  if (const std::string* choice = std::get_if<std::string>(&value)) return *choice;
  if (const Eigen::Vector3d* vector = std::get_if<Eigen::Vector3d>(&value)) {
    return nlohmann::json::array({vector->x(), vector->y(), vector->z()});
  }
  const double number = std::get<double>(value);
  if (spec.type == SettingType::integer) return static_cast<long>(number);
  return number;
}

}  // namespace wobble

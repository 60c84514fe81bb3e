#ifndef WOBBLE_IO_SETTING_JSON_H
#define WOBBLE_IO_SETTING_JSON_H

#include <nlohmann/json.hpp>

#include "sim/settings/setting_registry.h"

namespace wobble {

// A setting's value (sim/settings/setting_registry.h) as JSON, as scene files and --stats write
// it: a number, a whole number for an integer, true or false, a choice's name, or [x, y, z].
nlohmann::json setting_json(const SettingSpec& spec, const SettingValue& value);

}  // namespace wobble

#endif

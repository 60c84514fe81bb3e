#ifndef WOBBLE_IO_SCENE_WIND_H
#define WOBBLE_IO_SCENE_WIND_H

#include <string>

#include "io/json_fields.h"
#include "sim/forces/wind.h"

namespace wobble {

// The aerodynamic wind of a Wobble scene's "simulation": {"wind": {...}} object at `key`:
//   "velocity"     [x, y, z] air velocity (m/s), required, each within limits::speed
//   "drag"         C_d (default 1), "lift" C_l (default 0): limits::aerodynamic_coefficient
//   "gusts"        relative gust strength in [0, 1] (default 0: steady)
//   "air_density"  ρ (kg/m³, default 1.2)
//   "on"           true (default) or false: configured but off until --wind or the W key
// Other keys are refused by refuse_unknown_scene_keys. Throws InputError naming the file and
// the key path.
WindParams scene_wind(JsonFields& simulation, const std::string& key);

}  // namespace wobble

#endif

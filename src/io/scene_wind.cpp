#include "scene_wind.h"

#include "sim/input_error.h"
#include "sim/value_limits.h"

namespace wobble {

WindParams scene_wind(JsonFields& simulation, const std::string& key) {
  JsonFields fields = simulation.object(key);
  WindParams wind;
  wind.model = WindModel::aerodynamic;
  if (const std::optional<std::string> model = fields.text("model")) {
    if (*model == "course") {
      wind.model = WindModel::course;
    } else if (*model != "aerodynamic") {
      fields.fail("model", "\"aerodynamic\" or \"course\"");
    }
  }
  if (!fields.has("velocity")) {
    throw InputError(fields.where("velocity") +
                     ": missing, expected the air velocity [x, y, z] in m/s");
  }
  wind.velocity = *fields.vector3_in("velocity", limits::speed);
  wind.drag = fields.number_in("drag", limits::aerodynamic_coefficient).value_or(wind.drag);
  wind.lift = fields.number_in("lift", limits::aerodynamic_coefficient).value_or(wind.lift);
  wind.gusts = fields.number_in("gusts", limits::gust_strength).value_or(wind.gusts);
  wind.air_density =
      fields.number_in("air_density", limits::air_density).value_or(wind.air_density);
  wind.on = fields.flag("on").value_or(true);
  return wind;
}

}  // namespace wobble

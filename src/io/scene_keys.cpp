#include "scene_keys.h"

#include <nlohmann/json.hpp>
#include <optional>

#include "io/json_fields.h"
#include "sim/settings/setting_registry.h"

namespace wobble {

namespace {

// The object at `key` of `parent`, if there is one: a value of another type is the loader's to
// refuse, in its own words.
std::optional<JsonFields> child(JsonFields& parent, const std::string& key) {
  if (!parent.has(key) || !parent.raw(key).is_object()) return std::nullopt;
  return parent.object(key);
}

}  // namespace

void refuse_unknown_scene_keys(const std::string& path, const nlohmann::json& object) {
  JsonFields top(path, object);
  top.allow_only({"name", "description", "mesh", "material", "simulation", "colliders",
                  "self_collision", "pins", "initial_velocity", "camera", "appearance"},
                 "a Wobble scene");
  if (std::optional<JsonFields> mesh = child(top, "mesh")) {
    const nlohmann::json generator = mesh->has("generator") ? mesh->raw("generator") : nullptr;
    if (generator == "cloth") {
      mesh->allow_only(
          {"generator", "resolution", "size", "springs", "orientation", "height", "offset"},
          "a cloth generator's mesh");
    } else if (generator == "jelly") {
      mesh->allow_only({"generator", "resolution", "size", "offset"}, "a jelly generator's mesh");
    } else if (generator.is_null() && mesh->has("file")) {
      mesh->allow_only(
          {"file", "fill", "fill_resolution", "polygon_springs", "tetrahedra", "scale", "offset"},
          "a mesh read from a file");
    }
  }
  if (std::optional<JsonFields> material = child(top, "material")) {
    material->allow_only({"k", "density", "mass", "vertex_masses", "friction"}, "material");
  }
  if (std::optional<JsonFields> simulation = child(top, "simulation")) {
    // Every setting a scene keeps here (sim/settings/setting_registry.h) by its key, and those
    // read by their own readers.
    std::vector<std::string> keys;
    for (const SettingSpec& spec : all_settings()) {
      if (spec.places & in_scene) keys.push_back(setting_key(spec));
    }
    keys.insert(keys.end(), {"gravity", "contact_offset", "wind"});
    simulation->allow_only(keys, "simulation");
    if (std::optional<JsonFields> wind = child(*simulation, "wind")) {
      wind->allow_only({"velocity", "drag", "lift", "gusts", "air_density", "on", "model"},
                       "simulation.wind");
    }
  }
  if (std::optional<JsonFields> velocity = child(top, "initial_velocity")) {
    velocity->allow_only({"sway"}, "initial_velocity (an object)");
  }
  if (std::optional<JsonFields> camera = child(top, "camera")) {
    camera->allow_only({"position", "target"}, "camera");
  }
  if (std::optional<JsonFields> appearance = child(top, "appearance")) {
    appearance->allow_only({"front_color", "back_color", "texture"}, "appearance");
  }
}

}  // namespace wobble

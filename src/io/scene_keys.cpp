#include "scene_keys.h"

#include <algorithm>
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

// The keys the object at `section` holds for settings (sim/settings/setting_registry.h), in their
// order: the next key of every setting's path through it, and "on" for a section switch with a
// key; then `others`, what its own readers take.
std::vector<std::string> section_keys(const std::vector<std::string>& section,
                                      const std::vector<std::string>& others) {
  std::vector<std::string> keys, switches;
  for (const SettingSpec& spec : all_settings()) {
    if (!(spec.places & in_scene)) continue;
    const std::vector<std::string> path = scene_path(spec);
    if (path.size() > section.size() && std::equal(section.begin(), section.end(), path.begin()) &&
        std::find(keys.begin(), keys.end(), path[section.size()]) == keys.end()) {
      keys.push_back(path[section.size()]);
    } else if (path == section && spec.section_switch && spec.switch_key) {
      switches.push_back("on");
    }
  }
  keys.insert(keys.end(), switches.begin(), switches.end());
  keys.insert(keys.end(), others.begin(), others.end());
  return keys;
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
    material->allow_only(section_keys({"material"}, {"density", "mass", "vertex_masses"}),
                         "material");
  }
  if (std::optional<JsonFields> simulation = child(top, "simulation")) {
    simulation->allow_only(section_keys({"simulation"}, {"contact_offset"}), "simulation");
    if (std::optional<JsonFields> wind = child(*simulation, "wind"))
      wind->allow_only(section_keys({"simulation", "wind"}, {}), "simulation.wind");
  }
  if (std::optional<JsonFields> self_collision = child(top, "self_collision"))
    self_collision->allow_only(section_keys({"self_collision"}, {}), "self_collision");
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

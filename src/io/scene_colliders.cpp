#include "scene_colliders.h"

#include <algorithm>
#include <array>

#include "sim/input_error.h"
#include "sim/value_limits.h"
#include "text_pieces.h"

namespace wobble {

namespace {

struct ColliderKeys {
  ColliderType type;
  const char* name;
  std::vector<std::string> required;  // geometry keys a collider of this type must have
  std::vector<std::string> optional;
};

const std::array<ColliderKeys, 5>& collider_keys() {
  static const std::array<ColliderKeys, 5> keys = {{
      {ColliderType::ground, "ground", {}, {"height"}},
      {ColliderType::plane, "plane", {"point", "normal"}, {}},
      {ColliderType::sphere, "sphere", {"center", "radius"}, {}},
      {ColliderType::box, "box", {"center", "size"}, {}},
      {ColliderType::capsule, "capsule", {"from", "to", "radius"}, {}},
  }};
  return keys;
}

const char* const type_names = "\"ground\", \"plane\", \"sphere\", \"box\" or \"capsule\"";

// "center, radius, friction": what a collider of this type takes besides its type.
std::string key_list(const ColliderKeys& keys) {
  std::vector<std::string> all = keys.required;
  all.insert(all.end(), keys.optional.begin(), keys.optional.end());
  all.push_back("friction");
  return comma_joined(all);
}

bool belongs_to_some_type(const std::string& key) {
  for (const ColliderKeys& keys : collider_keys()) {
    const auto has = [&](const std::vector<std::string>& list) {
      return std::find(list.begin(), list.end(), key) != list.end();
    };
    if (has(keys.required) || has(keys.optional)) return true;
  }
  return false;
}

void check_keys(const nlohmann::json& object, const JsonFields& fields, const ColliderKeys& keys) {
  for (const auto& item : object.items()) {
    const std::string& key = item.key();
    const bool own = key == "type" || key == "friction" ||
                     std::count(keys.required.begin(), keys.required.end(), key) ||
                     std::count(keys.optional.begin(), keys.optional.end(), key);
    if (own) continue;
    throw InputError(fields.where(key) + ": " +
                     (belongs_to_some_type(key) ? "not a key of a " : "unknown key for a ") +
                     keys.name + " collider, which takes " + key_list(keys));
  }
  for (const std::string& key : keys.required) {
    if (!object.contains(key)) {
      throw InputError(fields.where(key) + ": missing, a " + keys.name + " collider needs " +
                       comma_joined(keys.required));
    }
  }
}

Collider read_collider(const std::string& file, const nlohmann::json& object,
                       const std::string& path) {
  if (!object.is_object()) {
    throw InputError(file + ": " + path + ": expected a collider object with a \"type\" of " +
                     type_names);
  }
  JsonFields fields(file, object, path);
  if (!fields.has("type")) {
    throw InputError(fields.where("type") + ": missing, expected " + type_names);
  }
  const std::string type = *fields.text("type");
  const auto& all = collider_keys();
  const auto found = std::find_if(all.begin(), all.end(),
                                  [&](const ColliderKeys& keys) { return keys.name == type; });
  if (found == all.end()) fields.fail("type", type_names);
  check_keys(object, fields, *found);

  Collider collider;
  collider.type = found->type;
  collider.friction = fields.number_in("friction", limits::friction).value_or(-1.0);
  switch (collider.type) {
    case ColliderType::ground:
      collider.height = fields.number_in("height", limits::coordinate).value_or(0.0);
      break;
    case ColliderType::plane:
      collider.center = *fields.vector3_in("point", limits::coordinate);
      collider.normal = *fields.vector3_in("normal", limits::coordinate);
      if (!(collider.normal.norm() > 1e-12)) fields.fail("normal", "a non-zero vector [x, y, z]");
      break;
    case ColliderType::sphere:
      collider.center = *fields.vector3_in("center", limits::coordinate);
      collider.radius = *fields.number_in("radius", limits::collider_size);
      break;
    case ColliderType::box:
      collider.center = *fields.vector3_in("center", limits::coordinate);
      collider.size = *fields.vector3_in("size", limits::collider_size);
      break;
    case ColliderType::capsule:
      collider.from = *fields.vector3_in("from", limits::coordinate);
      collider.to = *fields.vector3_in("to", limits::coordinate);
      collider.radius = *fields.number_in("radius", limits::collider_size);
      break;
  }
  // The simulation's own check, which also normalizes a plane's normal; everything it could
  // refuse was refused above with the key's name, so this names the collider only as a fallback.
  try {
    validate_collider(collider, path);
  } catch (const InputError& error) {
    throw InputError(file + ": " + error.what());
  }
  return collider;
}

}  // namespace

std::vector<Collider> scene_colliders(const std::string& file, JsonFields& top,
                                      const std::string& key) {
  const nlohmann::json& list = top.raw(key);
  if (!list.is_array()) top.fail(key, "a list of collider objects");
  if (list.size() > static_cast<std::size_t>(limits::max_colliders)) {
    throw InputError(top.where(key) + ": " + std::to_string(list.size()) +
                     " colliders, expected at most " + std::to_string(limits::max_colliders));
  }
  std::vector<Collider> colliders;
  for (std::size_t i = 0; i < list.size(); ++i)
    colliders.push_back(read_collider(file, list[i], key + "[" + std::to_string(i) + "]"));
  return colliders;
}

}  // namespace wobble

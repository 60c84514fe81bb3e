#include "shape_limits.h"

#include <initializer_list>
#include <utility>

#include "sim/input_error.h"
#include "sim/value_limits.h"

namespace wobble {

namespace {

// The keys among `keys` (in `section`) that the scene sets, as "mesh.scale and material.mass",
// for a message about what they gave together; `fallback` when it sets none of them.
std::string keys_set(const nlohmann::json& object,
                     std::initializer_list<std::pair<const char*, const char*>> keys,
                     const std::string& fallback) {
  std::string list;
  for (const auto& [section, key] : keys) {
    const auto found = object.find(section);
    if (found == object.end() || !found->is_object() || !found->contains(key)) continue;
    list += (list.empty() ? "" : " and ") + std::string(section) + "." + key;
  }
  return list.empty() ? fallback : list;
}

}  // namespace

void check_shape_limits(const std::string& path, const nlohmann::json& object,
                        const SpringNetwork& network) {
  const Eigen::Map<const Eigen::ArrayXd> coordinates(network.V.data(), network.V.size());
  const std::string positions =
      outside_limits(coordinates, limits::coordinate, "vertex coordinates");
  if (!positions.empty()) {
    const std::string keys = keys_set(
        object, {{"mesh", "scale"}, {"mesh", "offset"}, {"mesh", "height"}, {"mesh", "size"}},
        "mesh.file");
    throw InputError(path + ": " + keys + ": " + positions);
  }
  const std::string masses =
      outside_limits(network.m.array(), limits::vertex_mass, "vertex masses");
  if (!masses.empty()) {
    const std::string keys = keys_set(object,
                                      {{"material", "mass"},
                                       {"material", "density"},
                                       {"mesh", "scale"},
                                       {"mesh", "size"},
                                       {"mesh", "resolution"},
                                       {"mesh", "fill_resolution"}},
                                      "mesh.file");
    throw InputError(path + ": " + keys + ": " + masses);
  }
}

}  // namespace wobble

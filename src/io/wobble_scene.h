#ifndef WOBBLE_IO_WOBBLE_SCENE_H
#define WOBBLE_IO_WOBBLE_SCENE_H

#include <nlohmann/json.hpp>
#include <string>

#include "io/missing_texture.h"
#include "sim/scene.h"

namespace wobble {

// Whether a parsed JSON object is a Wobble scene: it has a "mesh".
bool is_wobble_scene(const nlohmann::json& object);

// Build the scene a Wobble scene file describes (docs/scenes.md, "Wobble's scene format",
// documents the format). `path` names the file in messages and anchors relative paths. An
// unknown key stops loading, as a wrong value does. Throws InputError naming the file, the key
// and what was expected (or, when `object` is not a JSON object with a "mesh", saying so).
// A texture that cannot be read is refused, or noted and left out (`missing_texture`).
Scene load_wobble_scene(const std::string& path, const nlohmann::json& object,
                        MissingTexture missing_texture = MissingTexture::refuse);

}  // namespace wobble

#endif

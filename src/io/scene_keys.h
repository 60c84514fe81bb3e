#ifndef WOBBLE_IO_SCENE_KEYS_H
#define WOBBLE_IO_SCENE_KEYS_H

#include <nlohmann/json_fwd.hpp>
#include <string>

namespace wobble {

// Refuse any key a Wobble scene (`object`, read from `path`) does not have, at every level,
// before anything is built or read: InputError "PATH: KEY.PATH: unknown key, WHAT takes KEYS",
// for the top, `mesh` (by its generator, or a file), `material`, `simulation` and its `wind`,
// `self_collision`, `initial_velocity` (as an object), `camera` and `appearance`. The sections
// that hold settings take the keys of the settings kept there (SettingSpec::scene_path) and those
// their own readers take. A misspelt key would otherwise run with its default without a word. A
// value of the wrong type is left to the loader, which names what it expected; the keys of each
// collider are checked where those are read (scene_colliders), in words of their own.
void refuse_unknown_scene_keys(const std::string& path, const nlohmann::json& object);

}  // namespace wobble

#endif

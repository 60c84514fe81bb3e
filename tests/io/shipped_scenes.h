#ifndef WOBBLE_TESTS_IO_SHIPPED_SCENES_H
#define WOBBLE_TESTS_IO_SHIPPED_SCENES_H

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/shapes/builtin_scenes.h"

namespace wobble::testing {

// Every scene Wobble ships, as load_scene takes them: the built-in names, then the scene files
// of `assets` and its subfolders (the course's in assets/course/), sorted. Listed, not named, so
// a new scene file is covered by whatever runs over them.
inline std::vector<std::string> shipped_scenes(const std::string& assets) {
  std::vector<std::string> scenes = builtin_scene_names();
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(assets)) {
    if (entry.path().extension() == ".json") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  scenes.insert(scenes.end(), files.begin(), files.end());
  return scenes;
}

}  // namespace wobble::testing

#endif

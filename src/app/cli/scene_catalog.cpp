#include "app/cli/scene_catalog.h"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <ostream>
#include <sstream>

#include "io/course_scene.h"
#include "io/load_scene.h"
#include "io/read_json_file.h"
#include "sim/contact/self_collision.h"
#include "sim/input_error.h"
#include "sim/shapes/builtin_scenes.h"

#ifndef WOBBLE_ASSETS_DIR
#define WOBBLE_ASSETS_DIR ""
#endif

namespace wobble {

std::vector<std::string> scene_catalog() {
  std::vector<std::string> sources = builtin_scene_names();
  std::vector<std::string> files;
  // The scene files of assets/ and of its subfolders (the course's scenes are in
  // assets/course/); an unreadable folder is skipped, not an error.
  std::error_code error;
  std::filesystem::recursive_directory_iterator entry(
      WOBBLE_ASSETS_DIR, std::filesystem::directory_options::skip_permission_denied, error);
  for (; !error && entry != std::filesystem::recursive_directory_iterator();
       entry.increment(error)) {
    if (entry->is_regular_file(error) && entry->path().extension() == ".json") {
      files.push_back(entry->path().string());
    }
  }
  std::sort(files.begin(), files.end());
  sources.insert(sources.end(), files.begin(), files.end());
  return sources;
}

std::string scene_label(const std::string& source) {
  const std::filesystem::path path(source);
  return path.has_extension() ? path.stem().string() : source;
}

bool is_course_scene_source(const std::string& source) {
  return std::filesystem::path(source).parent_path().filename() == "course";
}

std::string scene_description(const std::string& source) {
  const std::vector<std::string> builtins = builtin_scene_names();
  if (std::find(builtins.begin(), builtins.end(), source) != builtins.end())
    return make_builtin_scene(source).description;
  try {
    const nlohmann::json object = read_json_file(source);
    if (object.is_object() && object.contains("description") && object["description"].is_string())
      return object["description"].get<std::string>();
    if (is_course_scene(object)) {
      std::ostringstream text;
      text << "the course's scene: " << object.value("obj", std::string("its OBJ"));
      if (object.contains("k") && object["k"].is_number()) text << ", k = " << object["k"];
      if (object["b"].is_array()) text << ", " << object["b"].size() << " pins";
      return text.str();
    }
  } catch (const std::exception&) {
    // Said when the scene is chosen.
  }
  return "";
}

Scene open_scene(const CommandLine& command) {
  Scene scene = load_scene(command.scene, command.fill);
  apply_scene_overrides(command, scene.params);
  const SelfCollisionParams& self = scene.params.self_collision;
  if (self.on) {
    // A gap wider than the surface's own mesh cannot be kept (see SelfCollision): clamped, said.
    const double largest = largest_self_collision_thickness(scene.network);
    if (self.thickness > largest) {
      std::ostringstream note;
      note << (command.settings.has("self-collision-thickness") ? "--self-collision-thickness"
                                                                : "self_collision.thickness")
           << " " << self.thickness << " m is more than this mesh can keep between its layers"
           << " (1.5 times its mean edge); keeping " << largest << " m";
      scene.notes.push_back(note.str());
    }
  }
  return scene;
}

void print_notes(const Scene& scene, std::ostream& out) {
  for (const std::string& note : scene.notes)
    out << "wobble: note: " << escape_control_characters(note) << "\n";
}

}  // namespace wobble

#include "load_scene.h"

#include <algorithm>
#include <filesystem>
#include <limits>

#include "io/course_scene.h"
#include "io/input_file.h"
#include "io/load_mesh.h"
#include "io/read_json_file.h"
#include "io/scene_pins.h"
#include "io/wobble_scene.h"
#include "sim/input_error.h"
#include "sim/shapes/builtin_scenes.h"

namespace wobble {

namespace {

Scene bare_mesh_scene(const std::string& path, bool fill) {
  LoadedMesh mesh = load_mesh(path, fill);
  if (mesh.no_area) throw InputError(no_area_problem(path));
  Scene scene;
  scene.name = std::filesystem::path(path).stem().string();
  const bool volume = mesh.kind == LoadedMesh::Kind::volume;
  scene.description = std::string(volume ? "tetrahedral mesh " : "surface mesh ") + path;
  mesh.network.m *= volume ? 200.0 : (mesh.kind == LoadedMesh::Kind::surface ? 0.25 : 0.01);
  scene.params.k = volume ? 1500.0 : 400.0;
  // A cloth hangs from its top; a solid stands on its base.
  scene.pins = extreme_vertices(mesh.network.V, volume ? -1 : 1);
  const bool one = scene.pins.size() == 1;
  scene.notes.push_back("no pins given: pinned the " + std::to_string(scene.pins.size()) +
                        (volume ? " lowest" : " top-most") + (one ? " vertex" : " vertices") +
                        " of " + path);
  scene.network = std::move(mesh.network);
  if (mesh.uv.rows() == scene.network.V.rows()) scene.look.uv = mesh.uv;
  try {
    validate_spring_network(scene.network);
  } catch (const InputError& error) {
    throw InputError(path + ": " + error.what());
  }
  return scene;
}

}  // namespace

Scene load_scene(const std::string& source, bool fill, MissingTexture missing_texture) {
  const std::vector<std::string> builtins = builtin_scene_names();
  if (std::find(builtins.begin(), builtins.end(), source) != builtins.end()) {
    if (fill) throw InputError("--fill: only an OBJ surface can be filled, not '" + source + "'");
    return make_builtin_scene(source);
  }
  if (input_file_is_missing(source)) {
    std::string known;
    for (const std::string& name : builtins)
      known += (known.empty() ? "" : ", ") + name;
    throw InputError("'" + source + "': no such scene file or built-in scene (built-in: " + known +
                     ")");
  }
  // A folder, a FIFO, a device or a path that cannot be reached; each reader checks its own
  // size limit.
  const FileKind any_scene{"a scene file (.json) or a mesh (.obj, .mesh, .node or .ele)",
                           std::numeric_limits<std::uintmax_t>::max()};
  const std::string problem = input_file_problem(source, any_scene);
  if (!problem.empty()) throw InputError(source + ": " + problem);
  if (extension_of(source) == ".json") {
    if (fill) throw InputError("--fill: only an OBJ surface can be filled; set it in the scene");
    nlohmann::json object = read_json_file(source);
    const ReleaseJsonOnExit release(object);
    if (is_course_scene(object)) return load_course_scene(source, object, missing_texture);
    if (is_wobble_scene(object)) return load_wobble_scene(source, object, missing_texture);
    throw InputError(source +
                     ": not a scene: expected a Wobble scene (with \"mesh\") or a course scene "
                     "(with \"obj\" and \"b\")");
  }
  if (is_mesh_file(source)) return bare_mesh_scene(source, fill);
  throw InputError(source + ": unknown kind of file (expected .json, .obj, .mesh, .node or .ele)");
}

}  // namespace wobble

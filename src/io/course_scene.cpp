#include "course_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/input_file.h"
#include "io/input_file_limits.h"
#include "io/json_fields.h"
#include "io/png_image.h"
#include "io/read_json_file.h"
#include "io/read_obj.h"
#include "sim/input_error.h"
#include "sim/shapes/face_springs.h"
#include "sim/shapes/voronoi_masses.h"
#include "sim/value_limits.h"

namespace wobble {

namespace {

// The reference program's fixed settings.
constexpr double course_time_step = 1.0 / 30.0;
constexpr int course_iterations = 50;
constexpr double course_gravity = -9.8;

// A JSON value as it would be written, cut short so that a long list keeps the message short.
std::string shown(const nlohmann::json& value) {
  return json_preview(value);
}

// The keys a course scene has: the course's own reader takes these and no other.
const std::vector<std::string> course_keys = {"obj", "b", "k", "m", "png"};

InputError key_error(const std::string& json_path, const std::string& key,
                     const std::string& what) {
  return InputError(json_path + ": key `" + key + "`: " + what);
}

// A number within `range` (sim/value_limits.h: the same limits as the command line's and
// Wobble's scene files').
double number_in(const std::string& json_path, const nlohmann::json& object, const std::string& key,
                 const ValueRange& range) {
  const nlohmann::json& value = object.at(key);
  if (!value.is_number() || !range.contains(value.get<double>())) {
    throw key_error(json_path, key, "got " + shown(value) + ", expected " + expected_in(range));
  }
  return value.get<double>();
}

// A path given relative to the JSON file, which must name a file that `problem_of` finds
// nothing wrong with (input_file_problem, texture_problem).
template <typename ProblemOf>
std::string existing_file(const std::string& json_path, const nlohmann::json& object,
                          const std::string& key, const std::string& expected,
                          ProblemOf problem_of) {
  const nlohmann::json& value = object.at(key);
  if (!value.is_string() || value.get<std::string>().empty()) {
    throw key_error(json_path, key,
                    "got " + shown(value) + ", expected " + expected +
                        " path (a string, relative to the JSON file)");
  }
  const std::string resolved =
      (std::filesystem::path(json_path).parent_path() / value.get<std::string>()).string();
  const std::string problem = problem_of(resolved);
  if (!problem.empty()) throw key_error(json_path, key, "'" + resolved + "': " + problem);
  return resolved;
}

// "b": 1-based vertex indices, returned 0-based.
std::vector<int> pins(const std::string& json_path, const nlohmann::json& object,
                      Eigen::Index vertex_count) {
  const nlohmann::json& list = object.at("b");
  if (!list.is_array()) {
    throw key_error(json_path, "b",
                    "got " + shown(list) + ", expected a list of 1-based vertex indices");
  }
  const std::string range = "1 to " + std::to_string(vertex_count);
  std::vector<int> pinned;
  for (std::size_t entry = 0; entry < list.size(); ++entry) {
    const nlohmann::json& value = list[entry];
    const std::string at = "entry " + std::to_string(entry) + " is " + shown(value);
    // Any spelling of a whole number (4, 4.0, 4e0), as a JSON writer may give it.
    const std::optional<long long> index = whole_number(value, 1, vertex_count);
    if (!index) {
      const bool whole =
          value.is_number_integer() ||
          (value.is_number() && value.get<double>() == std::floor(value.get<double>()));
      throw key_error(json_path, "b",
                      at +
                          (whole ? ", expected a 1-based vertex index "
                                 : ", expected an integer vertex index ") +
                          range);
    }
    const int vertex = static_cast<int>(*index) - 1;
    if (std::find(pinned.begin(), pinned.end(), vertex) != pinned.end()) {
      throw key_error(json_path, "b", at + ", a vertex already pinned, expected each once");
    }
    pinned.push_back(vertex);
  }
  return pinned;
}

// The course's area masses, refused where a vertex has no area to give it one.
Eigen::VectorXd area_masses(const std::string& json_path, const SpringNetwork& network) {
  const Eigen::VectorXd masses = voronoi_masses(network.V, network.F);
  for (Eigen::Index i = 0; i < masses.size(); ++i) {
    if (!(masses(i) > 0.0)) {
      throw key_error(json_path, "m",
                      "missing, and vertex " + std::to_string(i + 1) +
                          " is in no triangle of non-zero area, so its Voronoi area mass is "
                          "undefined; expected `m`, one mass for every vertex");
    }
  }
  const std::string outside = outside_limits(masses.array(), limits::vertex_mass, "masses");
  if (!outside.empty()) {
    throw key_error(json_path, "m",
                    "missing, and the OBJ's Voronoi areas give " + outside +
                        "; expected `m`, one mass for every vertex, or a mesh of other size");
  }
  return masses;
}

}  // namespace

bool is_course_scene(const nlohmann::json& object) {
  return object.is_object() && object.contains("obj") && object.contains("b");
}

Scene load_course_scene(const std::string& json_path, const nlohmann::json& object,
                        MissingTexture missing_texture) {
  if (!is_course_scene(object)) {
    throw InputError(json_path +
                     ": not a course scene, expected a JSON object with keys `obj` and `b`");
  }
  if (object.contains("bc")) {
    throw key_error(json_path, "bc",
                    "boundary conditions are not supported, expected pins in `b` only");
  }
  // Any other key is refused too, as in Wobble's own format: a misspelt `m` would otherwise
  // give area masses without a word, and `colliders` or `self_collision` belong to the other
  // format.
  for (const auto& item : object.items()) {
    if (std::find(course_keys.begin(), course_keys.end(), item.key()) == course_keys.end()) {
      throw key_error(json_path, item.key(),
                      "unknown key, a course scene takes only obj, b, k, m and png");
    }
  }
  if (!object.contains("k")) {
    throw key_error(json_path, "k", "missing, expected the spring stiffness (a positive number)");
  }
  const double k = number_in(json_path, object, "k", limits::stiffness);
  const bool constant_mass = object.contains("m");
  const double m = constant_mass ? number_in(json_path, object, "m", limits::vertex_mass) : 0.0;
  const std::string obj_path =
      existing_file(json_path, object, "obj", "an OBJ mesh",
                    [](const std::string& path) { return input_file_problem(path, obj_file); });
  // The texture is checked now, though only drawing reads it, so that a scene is refused or
  // accepted whether or not it is drawn.
  std::string texture;
  std::string texture_note;
  if (object.contains("png")) {
    try {
      texture = existing_file(json_path, object, "png", "a PNG texture", texture_problem);
    } catch (const InputError& error) {
      if (missing_texture == MissingTexture::refuse) throw;
      texture_note = std::string(error.what()) + "; drawn without its texture";
    }
  }

  const ObjMesh mesh = read_obj(obj_path);
  Scene scene;
  scene.name = std::filesystem::path(json_path).stem().string();
  SpringNetwork& network = scene.network;
  network.V = mesh.V;
  network.E = face_springs(mesh.faces);
  network.F = fan_triangles(mesh.faces);
  network.m = constant_mass ? Eigen::VectorXd::Constant(mesh.V.rows(), m).eval()
                            : area_masses(json_path, network);
  try {
    validate_spring_network(network);
  } catch (const InputError& error) {
    throw InputError(json_path + ": " + error.what());
  }
  scene.pins = pins(json_path, object, mesh.V.rows());
  scene.description = "course scene: " + std::to_string(network.V.rows()) + " vertices, " +
                      std::to_string(network.E.rows()) + " springs";

  scene.params.k = k;
  scene.params.dt = course_time_step;
  scene.params.iterations = course_iterations;
  scene.params.gravity = Eigen::Vector3d(0.0, course_gravity, 0.0);
  scene.params.gravity_model = GravityModel::force_per_vertex;
  scene.params.first_iterate = FirstIterate::current_positions;
  // The course program's W key: off until --wind or the W key turns it on.
  scene.params.wind.model = WindModel::course;
  scene.params.wind.on = false;

  scene.look.uv = mesh.uv;
  scene.look.texture = texture;
  if (!texture_note.empty()) scene.notes.push_back(texture_note);
  if (!texture.empty() && mesh.uv.size() == 0) {
    scene.notes.push_back("the OBJ has no `vt` texture coordinates, so its texture cannot show");
  }
  return scene;
}

Scene load_course_scene(const std::string& json_path) {
  nlohmann::json object = read_json_file(json_path);
  const ReleaseJsonOnExit release(object);
  return load_course_scene(json_path, object);
}

}  // namespace wobble

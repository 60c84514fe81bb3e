#include "wobble_scene.h"

#include <cmath>
#include <filesystem>
#include <optional>

#include "io/json_fields.h"
#include "io/load_mesh.h"
#include "io/png_image.h"
#include "io/scene_colliders.h"
#include "io/scene_keys.h"
#include "io/scene_masses.h"
#include "io/scene_pins.h"
#include "io/shape_limits.h"
#include "sim/input_error.h"
#include "sim/settings/setting_registry.h"
#include "sim/shapes/cloth_grid.h"
#include "sim/shapes/jelly_block.h"
#include "sim/shapes/tet_mesh.h"
#include "sim/solver/solver_registry.h"
#include "sim/value_limits.h"

namespace wobble {

namespace {

// The shape and what kind of thing it is, before any material.
struct Shape {
  LoadedMesh mesh;
  int cloth_resolution = 0;  // > 0 for the cloth generator: its grid names pins
  double default_k = 400.0;
  std::string name;  // how messages name the mesh file, or "" for a generator
};

std::string relative_to(const std::string& scene_path, const std::string& file) {
  const std::filesystem::path path(file);
  if (path.is_absolute()) return file;
  return (std::filesystem::path(scene_path).parent_path() / path).lexically_normal().string();
}

// A generator's `offset` [x, y, z] (m): where its shape moves from where it is made.
void move_by_offset(JsonFields& mesh, Eigen::MatrixXd& V) {
  const std::optional<Eigen::Vector3d> offset = mesh.vector3_in("offset", limits::coordinate);
  if (offset) V.rowwise() += offset->transpose();
}

Shape cloth_shape(JsonFields& mesh) {
  ClothGridOptions options;
  options.resolution = mesh.whole("resolution", 2, limits::max_cloth_resolution).value_or(40);
  options.size = mesh.number_in("size", limits::size).value_or(1.0);
  options.areal_density = 1.0;  // masses come out as areas; the material scales them
  if (mesh.has("springs")) {
    const nlohmann::json& springs = mesh.raw("springs");
    if (!springs.is_array()) mesh.fail("springs", "a list of \"structural\", \"shear\", \"bend\"");
    options.structural = options.shear = options.bend = false;
    for (const nlohmann::json& kind : springs) {
      const std::string name = kind.is_string() ? kind.get<std::string>() : "";
      if (name == "structural") {
        options.structural = true;
      } else if (name == "shear") {
        options.shear = true;
      } else if (name == "bend") {
        options.bend = true;
      } else {
        mesh.fail("springs", "a list of \"structural\", \"shear\", \"bend\"");
      }
    }
  }
  const std::string orientation = mesh.text("orientation").value_or("horizontal");
  if (orientation != "horizontal" && orientation != "vertical") {
    mesh.fail("orientation", "\"horizontal\" or \"vertical\"");
  }
  const double height =
      mesh.number_in("height", limits::coordinate).value_or(orientation == "vertical" ? 1.6 : 1.2);

  Shape shape;
  shape.cloth_resolution = options.resolution;
  shape.mesh.kind = LoadedMesh::Kind::surface;
  shape.mesh.network = make_cloth_grid(options);
  Eigen::MatrixXd& V = shape.mesh.network.V;
  if (orientation == "vertical") {
    // Turn the sheet up about x so row 0 is the top edge at `height`, facing +z:
    // (x, y, z) → (x, −z, y), then lift.
    const Eigen::VectorXd z = V.col(2);
    V.col(2) = V.col(1);
    V.col(1) = -z.array() + (height - 0.5 * options.size);
  } else {
    V.col(1).array() += height;
  }
  move_by_offset(mesh, V);
  // Texture coordinates: u along columns, v up from the bottom row, as OBJ's vt.
  const int n = options.resolution;
  shape.mesh.uv.resize(n * n, 2);
  for (int row = 0; row < n; ++row) {
    for (int column = 0; column < n; ++column) {
      shape.mesh.uv.row(cloth_grid_vertex(n, row, column)) << column / double(n - 1),
          1.0 - row / double(n - 1);
    }
  }
  return shape;
}

Shape jelly_shape(JsonFields& mesh) {
  JellyBlockOptions options;
  options.resolution = mesh.whole("resolution", 1, limits::max_jelly_resolution).value_or(8);
  options.size = mesh.number_in("size", limits::size).value_or(0.5);
  options.density = 1.0;  // masses come out as volumes
  Shape shape;
  shape.mesh.kind = LoadedMesh::Kind::volume;
  shape.mesh.network = make_jelly_block(options);
  move_by_offset(mesh, shape.mesh.network.V);
  shape.default_k = 1500.0;
  return shape;
}

// A setting's value at `key` of its section (sim/settings/setting_registry.h), read by its
// type: a choice refused with the names to choose from ("solver": a registered solver's).
SettingValue scene_setting(JsonFields& simulation, const std::string& key,
                           const SettingSpec& spec) {
  switch (spec.type) {
    case SettingType::integer:
      return static_cast<double>(*simulation.whole(key, static_cast<int>(spec.range.low),
                                                   static_cast<int>(spec.range.high)));
    case SettingType::toggle:
      return *simulation.flag(key);
    case SettingType::choice: {
      const std::string choice = *simulation.text(key);
      const std::vector<std::string> names = spec.choices();
      std::string expected;
      for (std::size_t i = 0; i < names.size(); ++i) {
        if (choice == names[i]) return choice;
        expected += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ");
        expected += "\"" + names[i] + "\"";
      }
      simulation.fail(key, expected);
    }
    case SettingType::vector:
      if (!spec.number_along.isZero(0.0) && simulation.raw(key).is_number())
        return Eigen::Vector3d(*simulation.number_in(key, spec.range) * spec.number_along);
      return *simulation.vector3_in(key, spec.range);
    case SettingType::number:
      break;
  }
  return *simulation.number_in(key, spec.range);
}

// "tetrahedra": [[a, b, c, d], ...], 0-based indices into the mesh's vertices V, none flat (as a
// saved scene writes a solid's, beside its OBJ).
Eigen::MatrixXi tetrahedra_of(JsonFields& mesh, const Eigen::MatrixXd& V) {
  const nlohmann::json& list = mesh.raw("tetrahedra");
  const std::string expected = "a list of [a, b, c, d]: four distinct vertex indices from 0 to " +
                               std::to_string(V.rows() - 1) + ", not flat";
  if (!list.is_array() || list.empty()) mesh.fail("tetrahedra", expected);
  Eigen::MatrixXi T(static_cast<Eigen::Index>(list.size()), 4);
  for (std::size_t t = 0; t < list.size(); ++t) {
    const nlohmann::json& row = list[t];
    const std::string key = "tetrahedra[" + std::to_string(t) + "]";
    if (!row.is_array() || row.size() != 4) mesh.fail(key, expected);
    for (int c = 0; c < 4; ++c) {
      if (!row[c].is_number_integer() || row[c].get<long long>() < 0 ||
          row[c].get<long long>() >= V.rows()) {
        mesh.fail(key, expected);
      }
      T(static_cast<Eigen::Index>(t), c) = row[c].get<int>();
    }
    const auto corner = [&](int c) -> Eigen::Vector3d { return V.row(T(t, c)).transpose(); };
    if (tetrahedron_is_flat(corner(0), corner(1), corner(2), corner(3))) mesh.fail(key, expected);
  }
  return T;
}

Shape file_shape(const std::string& path, JsonFields& mesh) {
  const std::string file = relative_to(path, *mesh.text("file"));
  const std::string problem = mesh_file_problem(file);
  if (!problem.empty()) throw InputError(mesh.where("file") + ": " + problem);
  const bool fill = mesh.flag("fill").value_or(false);
  const int resolution = mesh.whole("fill_resolution", 2, limits::max_fill_resolution).value_or(12);
  const bool polygon_springs = mesh.flag("polygon_springs").value_or(true);
  if (!polygon_springs && (fill || extension_of(file) != ".obj")) {
    mesh.fail("polygon_springs", "true (false applies to an unfilled .obj only)");
  }
  Shape shape;
  shape.mesh = load_mesh(file, fill, resolution, mesh.where("fill_resolution"), polygon_springs);
  shape.name = mesh.where("file") + " '" + file + "'";
  const double scale = mesh.number_in("scale", limits::scale).value_or(1.0);
  const Eigen::Vector3d offset =
      mesh.vector3_in("offset", limits::coordinate).value_or(Eigen::Vector3d::Zero());
  SpringNetwork& network = shape.mesh.network;
  if (mesh.has("tetrahedra")) {
    if (polygon_springs) mesh.fail("tetrahedra", "to come with \"polygon_springs\": false");
    network.T = tetrahedra_of(mesh, network.V);
  }
  network.V = ((network.V * scale).rowwise() + offset.transpose()).eval();
  if (shape.mesh.kind == LoadedMesh::Kind::surface) network.m *= scale * scale;
  if (shape.mesh.kind == LoadedMesh::Kind::volume) network.m *= scale * scale * scale;
  if (shape.mesh.kind == LoadedMesh::Kind::volume) shape.default_k = 1500.0;
  return shape;
}

// visit(section) with the object at keys `first` to `depth` of `path` below `fields`, when the
// file has it; InputError for a value on the way that is not an object.
template <typename Visit>
void visit_section(JsonFields fields, const std::vector<std::string>& path, std::size_t first,
                   std::size_t depth, const Visit& visit) {
  if (first == depth) {
    visit(fields);
  } else if (fields.has(path[first])) {
    visit_section(fields.object(path[first]), path, first + 1, depth, visit);
  }
}

// Every setting a scene keeps (SettingPlace::in_scene: k and friction in "material", dt, the
// solver, gravity, the wind's section and the rest in "simulation", self-collision's section,
// each added setting), at its path, into params; one left out keeps the value params has. A
// section switch is on when its section is there, unless its "on" says otherwise.
void read_scene_settings(const JsonFields& top, SimulationParams& params) {
  for (const SettingSpec& spec : all_settings()) {
    if (!(spec.places & in_scene)) continue;
    const std::vector<std::string> path = scene_path(spec);
    const std::size_t depth = spec.section_switch ? path.size() : path.size() - 1;
    visit_section(top, path, 0, depth, [&](JsonFields& section) {
      if (spec.section_switch) {
        spec.set(params, spec.switch_key ? section.flag("on").value_or(true) : true);
      } else if (section.has(path.back())) {
        spec.set(params, scene_setting(section, path.back(), spec));
      } else if (spec.needed_in_section) {
        throw InputError(section.where(path.back()) + ": missing, expected the " + spec.label +
                         (spec.type == SettingType::vector ? " [x, y, z]" : "") + " in " +
                         spec.range.unit);
      }
    });
  }
}

}  // namespace

bool is_wobble_scene(const nlohmann::json& object) {
  return object.is_object() && object.contains("mesh");
}

Scene load_wobble_scene(const std::string& path, const nlohmann::json& object,
                        MissingTexture missing_texture) {
  if (!is_wobble_scene(object)) {
    throw InputError(path + ": not a Wobble scene, expected a JSON object with a \"mesh\"");
  }
  JsonFields top(path, object);
  // Unknown keys are refused, at every level, before anything is built.
  refuse_unknown_scene_keys(path, object);
  Scene scene;
  scene.name = top.text("name").value_or(std::filesystem::path(path).stem().string());
  scene.description = top.text("description").value_or("scene file " + path);

  JsonFields mesh = top.object("mesh");
  Shape shape;
  if (mesh.has("generator")) {
    const std::string generator = *mesh.text("generator");
    if (generator == "cloth") {
      shape = cloth_shape(mesh);
    } else if (generator == "jelly") {
      shape = jelly_shape(mesh);
    } else {
      mesh.fail("generator", "\"cloth\" or \"jelly\"");
    }
  } else if (mesh.has("file")) {
    shape = file_shape(path, mesh);
  } else {
    throw InputError(top.where("mesh") + ": expected a \"generator\" or a \"file\"");
  }

  scene.params.k = shape.default_k;
  read_scene_settings(top, scene.params);
  if (top.has("material")) {
    JsonFields material = top.object("material");
    scene_masses(material, shape.mesh, shape.name);
  } else {
    // JsonFields keeps a reference to its object, so the empty one must outlive it.
    const nlohmann::json empty = nlohmann::json::object();
    JsonFields none(path, empty);
    scene_masses(none, shape.mesh, shape.name);
  }
  check_shape_limits(path, object, shape.mesh.network);
  scene.network = std::move(shape.mesh.network);

  if (top.has("simulation")) {
    JsonFields simulation = top.object("simulation");
    scene.params.contact.offset =
        simulation.number_in("contact_offset", limits::contact_offset).value_or(-1.0);
  }
  if (top.has("colliders"))
    scene.params.contact.colliders = scene_colliders(path, top, "colliders");

  if (top.has("pins")) {
    scene.pins = scene_pins(top, "pins", scene.network.V, shape.cloth_resolution);
  }
  const Eigen::Index n = scene.network.V.rows();
  if (top.has("initial_velocity")) {
    const nlohmann::json& velocity = top.raw("initial_velocity");
    scene.initial_velocity = Eigen::MatrixXd::Zero(n, 3);
    if (velocity.is_object()) {
      // Sway: sideways (x) speed growing linearly with height, `sway` m/s at the top.
      JsonFields sway = top.object("initial_velocity");
      const double top_speed = sway.number_in("sway", limits::speed).value_or(0.0);
      const double low = scene.network.V.col(1).minCoeff();
      const double span = std::max(scene.network.V.col(1).maxCoeff() - low, 1e-12);
      scene.initial_velocity.col(0) = top_speed * (scene.network.V.col(1).array() - low) / span;
    } else {
      scene.initial_velocity.rowwise() =
          top.vector3_in("initial_velocity", limits::speed)->transpose();
    }
  }

  if (top.has("camera")) {
    JsonFields camera = top.object("camera");
    scene.look.camera_position = camera.vector3_in("position", limits::coordinate);
    scene.look.camera_target = camera.vector3_in("target", limits::coordinate);
    if (scene.look.camera_position.has_value() != scene.look.camera_target.has_value()) {
      camera.fail("target", "both a position and a target");
    }
  }
  if (top.has("appearance")) {
    JsonFields appearance = top.object("appearance");
    scene.look.front_color = appearance.color("front_color");
    scene.look.back_color = appearance.color("back_color");
    if (const std::optional<std::string> texture = appearance.text("texture")) {
      scene.look.texture = relative_to(path, *texture);
      // Checked now, though only drawing reads it, so that a scene is refused or accepted
      // whether or not it is drawn.
      const std::string problem = texture_problem(scene.look.texture);
      if (!problem.empty()) {
        const std::string why =
            appearance.where("texture") + ": '" + scene.look.texture + "': " + problem;
        if (missing_texture == MissingTexture::refuse) throw InputError(why);
        scene.notes.push_back(why + "; drawn without its texture");
        scene.look.texture.clear();
      } else if (shape.mesh.uv.rows() != n) {
        scene.notes.push_back(path + ": the mesh has no texture coordinates; texture ignored");
      }
    }
  }
  if (shape.mesh.uv.rows() == n) scene.look.uv = shape.mesh.uv;

  try {
    validate_spring_network(scene.network);
  } catch (const InputError& error) {
    throw InputError(path + ": " + error.what());
  }
  return scene;
}

}  // namespace wobble

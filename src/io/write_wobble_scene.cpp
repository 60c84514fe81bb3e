#include "write_wobble_scene.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <set>
#include <system_error>

#include "io/atomic_file.h"
#include "io/setting_json.h"
#include "sim/input_error.h"
#include "sim/settings/setting_registry.h"
#include "sim/solver/solver_registry.h"
#include "sim/value_limits.h"
#include "text_pieces.h"

namespace wobble {

namespace {

using nlohmann::json;

json vector_json(const Eigen::Vector3d& v) {
  return json::array({v.x(), v.y(), v.z()});
}

json collider_json(const Collider& collider) {
  json object;
  switch (collider.type) {
    case ColliderType::ground:
      object = {{"type", "ground"}, {"height", collider.height}};
      break;
    case ColliderType::plane:
      object = {{"type", "plane"},
                {"point", vector_json(collider.center)},
                {"normal", vector_json(collider.normal)}};
      break;
    case ColliderType::sphere:
      object = {{"type", "sphere"},
                {"center", vector_json(collider.center)},
                {"radius", collider.radius}};
      break;
    case ColliderType::box:
      object = {{"type", "box"},
                {"center", vector_json(collider.center)},
                {"size", vector_json(collider.size)}};
      break;
    case ColliderType::capsule:
      object = {{"type", "capsule"},
                {"from", vector_json(collider.from)},
                {"to", vector_json(collider.to)},
                {"radius", collider.radius}};
      break;
  }
  // A negative friction means "the material's", which is what leaving the key out says.
  if (collider.friction >= 0.0) object["friction"] = collider.friction;
  return object;
}

// Whether `section` begins `path`.
bool within(const std::vector<std::string>& section, const std::vector<std::string>& path) {
  return path.size() > section.size() && std::equal(section.begin(), section.end(), path.begin());
}

// The object at `path` in `top`, made where missing.
json& object_at(json& top, const std::vector<std::string>& path) {
  json* at = &top;
  for (const std::string& key : path)
    at = &(*at)[key];
  return *at;
}

// Every setting a scene keeps (SettingPlace::in_scene) at its path into `top`, the file's object.
// A choice or an added setting only when not its default, so that scenes saved before it was
// there and scenes that keep the default read and write the same; the rest always, to be read
// and changed. A section switch's section only while it is on, or, with an "on" key, while
// one of its settings is not its default: the section's presence is what turns it on.
void write_scene_settings(const SimulationParams& params, json& top) {
  const SimulationParams defaults;
  std::vector<std::vector<std::string>> left_out;
  for (const SettingSpec& switch_spec : all_settings()) {
    if (!(switch_spec.places & in_scene) || !switch_spec.section_switch) continue;
    const std::vector<std::string> section = scene_path(switch_spec);
    bool kept = std::get<bool>(switch_spec.get(params));
    for (const SettingSpec& spec : all_settings()) {
      if (switch_spec.switch_key && (spec.places & in_scene) && within(section, scene_path(spec)))
        kept = kept || spec.get(params) != spec.get(defaults);
    }
    if (!kept) {
      left_out.push_back(section);
      continue;
    }
    json& object = object_at(top, section);
    object = json::object();
    if (switch_spec.switch_key) object["on"] = std::get<bool>(switch_spec.get(params));
  }
  for (const SettingSpec& spec : all_settings()) {
    if (!(spec.places & in_scene) || spec.section_switch) continue;
    const std::vector<std::string> path = scene_path(spec);
    if (std::any_of(left_out.begin(), left_out.end(),
                    [&](const std::vector<std::string>& section) { return within(section, path); }))
      continue;
    const SettingValue value = spec.get(params);
    const bool quiet = spec.type == SettingType::choice || find_added_setting(spec.name);
    if (!quiet || value != spec.get(defaults)) object_at(top, path) = setting_json(spec, value);
  }
}

// The loader's sway, {"sway": s}, recomputed for a candidate s: it is kept only if it gives
// every vertex's velocity bit for bit.
bool is_sway(const Eigen::MatrixXd& V, const Eigen::MatrixXd& velocity, double top_speed) {
  const double low = V.col(1).minCoeff();
  const double span = std::max(V.col(1).maxCoeff() - low, 1e-12);
  const Eigen::VectorXd x = top_speed * (V.col(1).array() - low) / span;
  return velocity.col(0) == x && velocity.rightCols(2).isZero(0.0);
}

// The `initial_velocity` value that gives `velocity` back, or null when it is at rest.
json initial_velocity_json(const Scene& scene) {
  const Eigen::MatrixXd& velocity = scene.initial_velocity;
  if (velocity.size() == 0) return nullptr;
  if ((velocity.rowwise() - velocity.row(0)).isZero(0.0)) {
    return vector_json(velocity.row(0).transpose());
  }
  const Eigen::MatrixXd& V = scene.network.V;
  Eigen::Index top = 0;
  V.col(1).maxCoeff(&top);
  // The top vertex's speed is the sway's, up to the rounding of s·span/span.
  const double guess = velocity(top, 0);
  for (const double candidate :
       {guess, std::nextafter(guess, -INFINITY), std::nextafter(guess, INFINITY)}) {
    if (limits::speed.contains(candidate) && is_sway(V, velocity, candidate)) {
      return json{{"sway", candidate}};
    }
  }
  throw InputError(
      "the initial velocity differs from vertex to vertex other than as a sway, which a Wobble "
      "scene file cannot state; expected the same velocity for every vertex or a sway");
}

// `texture` as the saved scene names it: relative to the scene's folder when inside it.
std::string texture_reference(const std::string& texture, const std::string& json_path) {
  namespace fs = std::filesystem;
  const fs::path absolute = fs::absolute(texture).lexically_normal();
  const fs::path folder = fs::absolute(json_path).parent_path().lexically_normal();
  const fs::path relative = absolute.lexically_relative(folder);
  if (relative.empty() || *relative.begin() == "..") return absolute.string();
  return relative.string();
}

}  // namespace

nlohmann::json wobble_scene_json(const Scene& scene, const std::string& mesh_file,
                                 const std::string& texture) {
  const SimulationParams& params = scene.params;
  json masses = json::array();
  for (Eigen::Index i = 0; i < scene.network.m.size(); ++i)
    masses.push_back(scene.network.m(i));
  json material = {{"vertex_masses", std::move(masses)}};
  // Negative is the automatic offset, which is what leaving the key out gives.
  json simulation = json::object();
  if (params.contact.offset >= 0.0) simulation["contact_offset"] = params.contact.offset;

  json object = {{"name", scene.name},
                 {"description", scene.description},
                 {"mesh", {{"file", mesh_file}, {"polygon_springs", false}}},
                 {"pins", std::set<int>(scene.pins.begin(), scene.pins.end())},
                 {"material", std::move(material)},
                 {"simulation", std::move(simulation)}};
  write_scene_settings(params, object);
  // A solid's tetrahedra (its volume term's), which the OBJ does not hold.
  if (scene.network.T.rows() > 0) {
    json tetrahedra = json::array();
    for (Eigen::Index t = 0; t < scene.network.T.rows(); ++t) {
      tetrahedra.push_back({scene.network.T(t, 0), scene.network.T(t, 1), scene.network.T(t, 2),
                            scene.network.T(t, 3)});
    }
    object["mesh"]["tetrahedra"] = std::move(tetrahedra);
  }
  json colliders = json::array();
  for (const Collider& collider : params.contact.colliders)
    colliders.push_back(collider_json(collider));
  object["colliders"] = std::move(colliders);
  json velocity = initial_velocity_json(scene);
  if (!velocity.is_null()) object["initial_velocity"] = std::move(velocity);

  const SceneLook& look = scene.look;
  if (look.camera_position && look.camera_target) {
    object["camera"] = {{"position", vector_json(*look.camera_position)},
                        {"target", vector_json(*look.camera_target)}};
  }
  json appearance = json::object();
  if (look.front_color) appearance["front_color"] = vector_json(*look.front_color);
  if (look.back_color) appearance["back_color"] = vector_json(*look.back_color);
  if (!texture.empty()) appearance["texture"] = texture;
  if (!appearance.empty()) object["appearance"] = std::move(appearance);
  return object;
}

std::string wobble_scene_obj_text(const Scene& scene) {
  const SpringNetwork& network = scene.network;
  const bool uv = scene.look.uv.rows() == network.V.rows() && scene.look.uv.cols() == 2;
  std::string text =
      "# Wobble scene mesh: render triangles, then every spring as a two-vertex face\n";
  for (Eigen::Index i = 0; i < network.V.rows(); ++i) {
    text += "v";
    for (int c = 0; c < 3; ++c) {
      text += ' ';
      append_shortest(text, network.V(i, c));
    }
    text += '\n';
  }
  if (uv) {
    for (Eigen::Index i = 0; i < network.V.rows(); ++i) {
      text += "vt ";
      append_shortest(text, scene.look.uv(i, 0));
      text += ' ';
      append_shortest(text, scene.look.uv(i, 1));
      text += '\n';
    }
  }
  // Vertex i's texture coordinate is `vt` i, so every corner is written "n/n" (1-based).
  const auto corner = [&](int vertex) {
    const std::string index = std::to_string(vertex + 1);
    return uv ? index + "/" + index : index;
  };
  for (Eigen::Index f = 0; f < network.F.rows(); ++f) {
    text += "f " + corner(network.F(f, 0)) + " " + corner(network.F(f, 1)) + " " +
            corner(network.F(f, 2)) + "\n";
  }
  // Two-vertex faces, not `l` lines: only faces carry texture coordinates to their vertices.
  for (Eigen::Index e = 0; e < network.E.rows(); ++e)
    text += "f " + corner(network.E(e, 0)) + " " + corner(network.E(e, 1)) + "\n";
  return text;
}

void write_wobble_scene(const std::string& json_path, const Scene& scene) {
  namespace fs = std::filesystem;
  const std::string mesh_path = fs::path(json_path).replace_extension(".obj").string();
  if (mesh_path == json_path) {
    throw InputError("save scene: '" + json_path +
                     "' ends in .obj, which is where its mesh goes; expected a .json file name");
  }
  check_output_path("save scene", json_path);
  check_output_path("save scene", mesh_path);
  const std::string texture =
      scene.look.texture.empty() ? "" : texture_reference(scene.look.texture, json_path);
  std::string json_text;
  try {
    json_text =
        wobble_scene_json(scene, fs::path(mesh_path).filename().string(), texture).dump(2) + "\n";
  } catch (const InputError& error) {
    throw InputError("save scene: '" + json_path + "': " + error.what());
  }

  std::error_code ignored;
  const bool mesh_existed = fs::exists(mesh_path, ignored);
  write_output_file(mesh_path, wobble_scene_obj_text(scene));
  try {
    write_output_file(json_path, json_text);
  } catch (...) {
    if (!mesh_existed) fs::remove(mesh_path, ignored);
    throw;
  }
}

}  // namespace wobble

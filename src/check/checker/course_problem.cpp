#include "course_problem.h"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace {

std::runtime_error problem(const std::string& path, const std::string& what) {
  return std::runtime_error(path + ": " + what);
}

// An OBJ face or line index, 1-based or negative (counted back from the last vertex so far),
// before any "/vt/vn" part; into a 0-based index.
int obj_index(const std::string& token, int vertices_so_far, const std::string& where) {
  int index = 0;
  try {
    index = std::stoi(token.substr(0, token.find('/')));
  } catch (const std::exception&) {
    throw std::runtime_error(where + ": expected a vertex index, found '" + token + "'");
  }
  const int zero_based = index < 0 ? vertices_so_far + index : index - 1;
  if (index == 0 || zero_based < 0 || zero_based >= vertices_so_far)
    throw std::runtime_error(where + ": vertex index " + token + " out of range");
  return zero_based;
}

void read_obj(const std::string& path, Eigen::MatrixXd& V, Eigen::MatrixXi& E) {
  std::ifstream in(path);
  if (!in) throw problem(path, "cannot open the OBJ file");
  std::vector<Eigen::RowVector3d> vertices;
  std::vector<std::vector<int>> faces;
  std::string line;
  for (int line_number = 1; std::getline(in, line); ++line_number) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    const std::string where = path + ": line " + std::to_string(line_number);
    if (keyword == "v") {
      Eigen::RowVector3d p;
      if (!(words >> p(0) >> p(1) >> p(2))) throw std::runtime_error(where + ": expected v x y z");
      vertices.push_back(p);
    } else if (keyword == "f" || keyword == "l") {
      std::vector<int> face;
      for (std::string token; words >> token;)
        face.push_back(obj_index(token, static_cast<int>(vertices.size()), where));
      if (face.size() < 2) throw std::runtime_error(where + ": a face needs 2 or more vertices");
      if (keyword == "l") {
        // A polyline is its segments, each a two-vertex face.
        for (size_t s = 0; s + 1 < face.size(); ++s)
          faces.push_back({face[s], face[s + 1]});
      } else {
        faces.push_back(face);
      }
    }
  }
  if (vertices.empty()) throw problem(path, "no vertices");
  V.resize(static_cast<int>(vertices.size()), 3);
  for (int i = 0; i < V.rows(); ++i)
    V.row(i) = vertices[i];

  std::vector<std::pair<int, int>> springs;
  const bool only_pairs =
      std::all_of(faces.begin(), faces.end(), [](const auto& f) { return f.size() == 2; });
  if (only_pairs) {
    for (const auto& f : faces)
      springs.emplace_back(f[0], f[1]);
  } else {
    std::set<std::pair<int, int>> unique;
    for (const auto& f : faces)
      for (size_t a = 0; a < f.size(); ++a)
        for (size_t c = a + 1; c < f.size(); ++c)
          if (f[a] != f[c]) unique.emplace(std::min(f[a], f[c]), std::max(f[a], f[c]));
    springs.assign(unique.begin(), unique.end());
  }
  if (springs.empty()) throw problem(path, "no springs (faces or lines)");
  E.resize(static_cast<int>(springs.size()), 2);
  for (int e = 0; e < E.rows(); ++e)
    E.row(e) << springs[e].first, springs[e].second;
}

}  // namespace

CheckScene load_course_problem(const std::string& json_path, int steps) {
  std::ifstream in(json_path);
  if (!in) throw problem(json_path, "cannot open the course scene");
  nlohmann::json object;
  try {
    in >> object;
  } catch (const std::exception& error) {
    throw problem(json_path, std::string("malformed JSON: ") + error.what());
  }
  if (!object.is_object() || !object.contains("obj") || !object["obj"].is_string())
    throw problem(json_path, "expected a JSON object with \"obj\"");
  if (!object.contains("b") || !object["b"].is_array())
    throw problem(json_path, "expected \"b\", a list of 1-based vertex indices");
  if (!object.contains("k") || !object["k"].is_number() || !(object["k"].get<double>() > 0))
    throw problem(json_path, "expected \"k\", a positive number");

  const std::string folder = json_path.substr(0, json_path.find_last_of('/') + 1);
  CheckScene scene;
  read_obj(folder + object["obj"].get<std::string>(), scene.V, scene.E);
  const int n = static_cast<int>(scene.V.rows());
  scene.b.resize(static_cast<int>(object["b"].size()));
  for (int c = 0; c < scene.b.size(); ++c) {
    const auto& entry = object["b"][c];
    if (!entry.is_number_integer() || entry.get<int>() < 1 || entry.get<int>() > n)
      throw problem(json_path, "\"b\" entry " + std::to_string(c) + " is not a vertex index 1.." +
                                   std::to_string(n));
    scene.b(c) = entry.get<int>() - 1;
  }
  scene.k = object["k"].get<double>();
  double mass = 1.0;
  if (object.contains("m")) {
    if (!object["m"].is_number() || !(object["m"].get<double>() > 0))
      throw problem(json_path, "\"m\" must be a positive number");
    mass = object["m"].get<double>();
  }
  scene.m = Eigen::VectorXd::Constant(n, mass);
  scene.delta_t = 1.0 / 30.0;
  scene.fext = Eigen::MatrixXd::Zero(n, 3);
  scene.fext.col(1).setConstant(-9.8);
  scene.Uprev = scene.V;
  scene.Ucur = scene.V;
  scene.steps = steps;
  const std::string name = json_path.substr(json_path.find_last_of('/') + 1);
  scene.description = "the course scene " + name + " (" + std::to_string(n) + " vertices, " +
                      std::to_string(scene.E.rows()) + " springs)";
  return scene;
}

#include "scene_pins.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include "sim/input_error.h"
#include "sim/shapes/cloth_grid.h"

namespace wobble {

namespace {

const char* const expected_pins =
    "a vertex index, \"top\", \"bottom\", \"top-edge\", \"top-corners\", \"corners\", "
    "\"left-edge\", \"none\", {\"below\": metres}, {\"above\": metres}, or a list of these";

// {"below": h}: every vertex within h of the lowest; {"above": h}: within h of the highest.
void add_band(JsonFields& fields, const std::string& key, const nlohmann::json& band,
              const Eigen::MatrixXd& V, std::set<int>& pins) {
  const bool below = band.contains("below");
  // Only a key that is there may be looked up: operator[] of a const object has no entry to
  // return for a missing one (undefined behaviour; nlohmann asserts).
  if (band.size() != 1 || (!below && !band.contains("above"))) fields.fail(key, expected_pins);
  const nlohmann::json& height = band.at(below ? "below" : "above");
  if (!height.is_number() || !(height.get<double>() >= 0.0)) fields.fail(key, expected_pins);
  const double h = height.get<double>();
  const double low = V.col(1).minCoeff(), high = V.col(1).maxCoeff();
  for (Eigen::Index i = 0; i < V.rows(); ++i) {
    if (below ? V(i, 1) <= low + h : V(i, 1) >= high - h) pins.insert(static_cast<int>(i));
  }
}

void add_selection(JsonFields& fields, const std::string& key, const std::string& name,
                   const Eigen::MatrixXd& V, int n, std::set<int>& pins) {
  if (name == "none") return;
  if (name == "top" || name == "bottom") {
    for (int i : extreme_vertices(V, name == "top" ? 1 : -1))
      pins.insert(i);
    return;
  }
  const bool grid_name =
      name == "top-edge" || name == "top-corners" || name == "corners" || name == "left-edge";
  if (!grid_name) fields.fail(key, expected_pins);
  if (n <= 0) fields.fail(key, "\"" + name + "\" only on the cloth generator; use \"top\"");
  for (int j = 0; j < n; ++j) {
    if (name == "top-edge") pins.insert(cloth_grid_vertex(n, 0, j));
    if (name == "left-edge") pins.insert(cloth_grid_vertex(n, j, 0));
  }
  if (name == "top-corners" || name == "corners") {
    pins.insert(cloth_grid_vertex(n, 0, 0));
    pins.insert(cloth_grid_vertex(n, 0, n - 1));
  }
  if (name == "corners") {
    pins.insert(cloth_grid_vertex(n, n - 1, 0));
    pins.insert(cloth_grid_vertex(n, n - 1, n - 1));
  }
}

}  // namespace

std::vector<int> extreme_vertices(const Eigen::MatrixXd& V, int extreme) {
  std::vector<int> chosen;
  if (V.rows() == 0) return chosen;
  const double size = (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm();
  const double level = extreme > 0 ? V.col(1).maxCoeff() : V.col(1).minCoeff();
  for (Eigen::Index i = 0; i < V.rows(); ++i) {
    if (std::abs(V(i, 1) - level) <= 1e-6 * size) chosen.push_back(static_cast<int>(i));
  }
  return chosen;
}

std::vector<int> scene_pins(JsonFields& fields, const std::string& key, const Eigen::MatrixXd& V,
                            int cloth_resolution) {
  std::set<int> pins;
  const auto add = [&](const nlohmann::json& item) {
    if (item.is_string()) {
      add_selection(fields, key, item.get<std::string>(), V, cloth_resolution, pins);
    } else if (item.is_object()) {
      add_band(fields, key, item, V, pins);
    } else if (item.is_number()) {
      // Any spelling of a whole number: 3, 3.0, 3e0.
      const std::optional<long long> index = whole_number(item, 0, V.rows() - 1);
      if (!index) {
        const double x = item.get<double>();
        const bool whole = item.is_number_integer() || x == std::floor(x);
        throw InputError(
            fields.where(key) + ": vertex index " + json_preview(item) +
            (whole ? " is out of range (0 to " : " is not a whole number (expected 0 to ") +
            std::to_string(V.rows() - 1) + ")");
      }
      pins.insert(static_cast<int>(*index));
    } else {
      fields.fail(key, expected_pins);
    }
  };
  // The list is read where it is, not copied: it may hold an item for every vertex.
  const nlohmann::json& value = fields.raw(key);
  if (value.is_array()) {
    for (const nlohmann::json& item : value)
      add(item);
  } else {
    add(value);
  }
  return std::vector<int>(pins.begin(), pins.end());
}

}  // namespace wobble

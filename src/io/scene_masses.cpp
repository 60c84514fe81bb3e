#include "scene_masses.h"

#include <optional>
#include <string>

#include "sim/input_error.h"
#include "sim/value_limits.h"

namespace wobble {

namespace {

// `vertex_masses`: one mass (kg) for every vertex, as a saved scene stores them exactly.
Eigen::VectorXd vertex_masses(JsonFields& material, Eigen::Index vertex_count) {
  const nlohmann::json& list = material.raw("vertex_masses");
  const std::string expected = "a list of " + std::to_string(vertex_count) +
                               " masses, one for every vertex, each " +
                               within_text(limits::vertex_mass);
  if (!list.is_array() || static_cast<Eigen::Index>(list.size()) != vertex_count) {
    material.fail("vertex_masses", expected);
  }
  Eigen::VectorXd m(vertex_count);
  for (Eigen::Index i = 0; i < vertex_count; ++i) {
    const nlohmann::json& item = list[static_cast<std::size_t>(i)];
    if (!item.is_number() || !limits::vertex_mass.contains(item.get<double>())) {
      throw InputError(material.where("vertex_masses") + "[" + std::to_string(i) +
                       "]: expected a mass " + within_text(limits::vertex_mass) + ", got " +
                       json_preview(item));
    }
    m(i) = item.get<double>();
  }
  return m;
}

}  // namespace

void scene_masses(JsonFields& material, LoadedMesh& mesh, const std::string& mesh_name) {
  if (material.has("density") && material.has("mass")) {
    material.fail("mass", "either density or mass, not both");
  }
  if (material.has("vertex_masses") && (material.has("density") || material.has("mass"))) {
    material.fail("vertex_masses", "either vertex_masses or a density or mass, not both");
  }
  if (material.has("vertex_masses")) {
    mesh.network.m = vertex_masses(material, mesh.network.V.rows());
    return;
  }
  if (mesh.no_area) {
    throw InputError(no_area_problem(mesh_name) +
                     ", or material.vertex_masses giving every vertex its mass");
  }
  const double default_density = mesh.kind == LoadedMesh::Kind::volume    ? 200.0
                                 : mesh.kind == LoadedMesh::Kind::surface ? 0.25
                                                                          : 0.01;
  Eigen::VectorXd& m = mesh.network.m;
  if (const std::optional<double> mass = material.number_in("mass", limits::total_mass)) {
    m *= *mass / m.sum();
  } else {
    m *= material.number_in("density", limits::density).value_or(default_density);
  }
}

}  // namespace wobble

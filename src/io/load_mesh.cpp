#include "load_mesh.h"

#include <algorithm>
#include <cctype>
#include <utility>
#include <vector>

#include "io/input_file.h"
#include "io/input_file_limits.h"
#include "io/read_medit_mesh.h"
#include "io/read_obj.h"
#include "io/read_tetgen.h"
#include "sim/input_error.h"
#include "sim/input_limits.h"
#include "sim/shapes/face_springs.h"
#include "sim/shapes/tet_mesh.h"
#include "sim/shapes/tetrahedralize_surface.h"
#include "sim/shapes/voronoi_masses.h"
#include "sim/value_limits.h"

namespace wobble {

namespace {

// Springs, boundary and volume weights of a tetrahedral mesh, without unused vertices (they would
// have no mass and no spring, which makes the system singular).
LoadedMesh volume_mesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T) {
  std::vector<int> new_index(V.rows(), -1);
  int used = 0;
  for (Eigen::Index t = 0; t < T.rows(); ++t) {
    for (int c = 0; c < 4; ++c) {
      if (new_index[T(t, c)] < 0) new_index[T(t, c)] = used++;
    }
  }
  // Keep the file's order among the vertices that stay.
  used = 0;
  for (int& index : new_index) {
    if (index >= 0) index = used++;
  }
  LoadedMesh mesh;
  mesh.kind = LoadedMesh::Kind::volume;
  SpringNetwork& network = mesh.network;
  network.V.resize(used, 3);
  for (Eigen::Index i = 0; i < V.rows(); ++i) {
    if (new_index[i] >= 0) network.V.row(new_index[i]) = V.row(i);
  }
  Eigen::MatrixXi tets(T.rows(), 4);
  for (Eigen::Index t = 0; t < T.rows(); ++t) {
    for (int c = 0; c < 4; ++c)
      tets(t, c) = new_index[T(t, c)];
  }
  network.E = tet_mesh_edges(tets);
  network.F = tet_mesh_boundary_faces(network.V, tets);
  network.m = tet_mesh_lumped_masses(network.V, tets, 1.0);
  network.T = std::move(tets);
  return mesh;
}

LoadedMesh obj_mesh(const std::string& path, bool fill, int fill_resolution,
                    const std::string& fill_key, bool polygon_springs) {
  const ObjMesh obj = read_obj(path);
  const Eigen::MatrixXi triangles = fan_triangles(obj.faces);
  if (fill) {
    if (triangles.rows() == 0) {
      throw InputError(path + ": has no faces to fill with tetrahedra");
    }
    const double pairs = tetrahedralize_surface_pairs(obj.V, triangles.rows(), fill_resolution);
    if (pairs > limits::max_fill_pairs) {
      throw InputError(fill_key + ": filling " + path + " (" +
                       with_thousands_separators(triangles.rows()) + " triangles) at resolution " +
                       std::to_string(fill_resolution) + " takes " + limit_text(pairs, 3) +
                       " cell-triangle tests, above the limit of " +
                       limit_text(limits::max_fill_pairs) +
                       ": expected a lower resolution or a coarser surface");
    }
    Eigen::MatrixXd TV;
    Eigen::MatrixXi TT;
    try {
      tetrahedralize_surface(obj.V, triangles, fill_resolution, TV, TT);
    } catch (const InputError& error) {
      throw InputError(path + ": cannot fill: " + error.what());
    }
    return volume_mesh(TV, TT);
  }
  LoadedMesh mesh;
  mesh.network.V = obj.V;
  if (polygon_springs) {
    mesh.network.E = face_springs(obj.faces);
  } else {
    std::vector<std::vector<int>> two_vertex_faces;
    for (const std::vector<int>& face : obj.faces) {
      if (face.size() == 2) two_vertex_faces.push_back(face);
    }
    if (two_vertex_faces.empty()) {
      throw InputError(path + ": no two-vertex faces or `l` lines, expected the springs there " +
                       "since the scene's mesh.polygon_springs is false");
    }
    mesh.network.E = face_springs(two_vertex_faces);
  }
  mesh.network.F = triangles;
  mesh.uv = obj.uv;
  if (triangles.rows() == 0) {
    mesh.kind = LoadedMesh::Kind::lines;
    mesh.network.m = Eigen::VectorXd::Ones(obj.V.rows());
  } else {
    mesh.kind = LoadedMesh::Kind::surface;
    mesh.network.m = voronoi_masses(obj.V, triangles);
    // Whether that is wrong depends on the scene: a saved scene gives every vertex its mass.
    if (!(mesh.network.m.sum() > 0.0)) {
      mesh.no_area = true;
      mesh.network.m.setZero();
      return mesh;
    }
    // A vertex on no face (only on l lines) has no area; give it the mean so it has a mass.
    const double mean = mesh.network.m.sum() / static_cast<double>(mesh.network.m.size());
    for (Eigen::Index i = 0; i < mesh.network.m.size(); ++i) {
      if (!(mesh.network.m(i) > 0.0)) mesh.network.m(i) = mean;
    }
  }
  return mesh;
}

}  // namespace

std::string no_area_problem(const std::string& path) {
  return path + ": every face has zero area, so no vertex gets a mass from its area; expected " +
         "faces whose corners are not all on one line";
}

std::string extension_of(const std::string& path) {
  const std::size_t dot = path.rfind('.');
  const std::size_t slash = path.rfind('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string extension = path.substr(dot);
  for (char& c : extension)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

bool is_mesh_file(const std::string& path) {
  const std::string extension = extension_of(path);
  return extension == ".obj" || extension == ".mesh" || extension == ".node" || extension == ".ele";
}

std::string mesh_file_problem(const std::string& path) {
  const std::string extension = extension_of(path);
  std::vector<std::pair<std::string, FileKind>> files;
  if (extension == ".obj") {
    files = {{path, obj_file}};
  } else if (extension == ".mesh") {
    files = {{path, medit_file}};
  } else if (extension == ".node" || extension == ".ele") {
    // The file named first, then the one beside it that read_tetgen reads too.
    const std::string base = tetgen_base(path);
    files = {{base + ".node", tetgen_node_file}, {base + ".ele", tetgen_ele_file}};
    if (path == base + ".ele") std::swap(files[0], files[1]);
  } else {
    return "'" + path + "': unknown mesh format, expected .obj, .mesh, .node or .ele";
  }
  for (const auto& [file, kind] : files) {
    const std::string problem = input_file_problem(file, kind);
    if (!problem.empty()) return "'" + file + "': " + problem;
  }
  return "";
}

LoadedMesh load_mesh(const std::string& path, bool fill, int fill_resolution,
                     const std::string& fill_key, bool polygon_springs) {
  const std::string extension = extension_of(path);
  if (extension == ".obj") return obj_mesh(path, fill, fill_resolution, fill_key, polygon_springs);
  if (fill) throw InputError(path + ": only an OBJ surface can be filled with tetrahedra");
  if (extension == ".mesh") {
    const TetMeshFile file = read_medit_mesh(path);
    return volume_mesh(file.V, file.T);
  }
  if (extension == ".node" || extension == ".ele") {
    const TetMeshFile file = read_tetgen(path);
    return volume_mesh(file.V, file.T);
  }
  throw InputError(path + ": unknown mesh format (expected .obj, .mesh, .node or .ele)");
}

}  // namespace wobble

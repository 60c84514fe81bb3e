#ifndef WOBBLE_IO_LOAD_MESH_H
#define WOBBLE_IO_LOAD_MESH_H

#include <Eigen/Core>
#include <string>

#include "sim/spring_network.h"

namespace wobble {

// A spring network read from a mesh file, before any material is chosen.
struct LoadedMesh {
  // V, E and F as simulated; m holds mass weights, not masses: the area around each vertex
  // (m², surfaces), the volume (m³, tetrahedral meshes) or 1 (networks of lines only).
  SpringNetwork network;
  Eigen::MatrixXd uv;  // #V by 2 from the OBJ's vt, or empty
  enum class Kind { surface, volume, lines } kind = Kind::surface;
  // A surface whose every face has zero area: its weights are all 0, so masses must be given
  // vertex by vertex (a saved scene's material.vertex_masses); see no_area_problem.
  bool no_area = false;
};

// "PATH: every face has zero area, so no vertex gets a mass from its area; expected ...": why
// a mesh with LoadedMesh::no_area cannot take its masses from its area (a density, a total mass,
// or the defaults).
std::string no_area_problem(const std::string& path);

// Read a mesh file by its extension:
//   .obj          springs as face_springs builds them (every two vertices of each larger face
//                 once; each two-vertex face and `l` segment as written), render faces
//                 fan-triangulated, weights = lumped Voronoi areas; with `fill`, the closed
//                 surface is filled with tetrahedra (voxel grid of `fill_resolution` cells along
//                 its longest side) and simulated as a volume
//   .mesh         MEDIT tetrahedra
//   .node / .ele  TetGen tetrahedra (either file of the pair)
// Tetrahedral meshes: springs are the edges, render faces the boundary, weights the lumped
// volumes; vertices no tetrahedron uses are dropped. Throws InputError naming the file. An OBJ
// surface whose faces all have zero area is not refused here (see LoadedMesh::no_area): only
// masses taken from areas need them.
// A fill above limits::max_fill_pairs is refused at once, naming `fill_key` (the option or the
// scene key that asked for it).
// With `polygon_springs` false (an OBJ only, not filled), faces of three or more vertices are
// drawn but give no spring: the springs are exactly the two-vertex faces and `l` segments, in
// file order, so a network whose springs are not its triangles' edges is stored exactly.
LoadedMesh load_mesh(const std::string& path, bool fill = false, int fill_resolution = 12,
                     const std::string& fill_key = "--fill", bool polygon_springs = true);

// Why `path` cannot be read by load_mesh, or "": its extension is unknown, or a file it would
// read (for TetGen both BASE.node and BASE.ele) is not a regular file within its format's size
// limit (input_file_problem). Looks at the files' status only, so it never blocks. The answer
// names the file at fault: "'PATH': is a folder, expected a TetGen .node file".
std::string mesh_file_problem(const std::string& path);

// The extension of a file name, lower-cased, with its dot (".obj"), or "" if it has none.
std::string extension_of(const std::string& path);

// Whether `path` ends in an extension load_mesh reads.
bool is_mesh_file(const std::string& path);

}  // namespace wobble

#endif

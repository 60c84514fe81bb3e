#ifndef WOBBLE_IO_READ_OBJ_H
#define WOBBLE_IO_READ_OBJ_H

#include <Eigen/Core>
#include <string>
#include <vector>

namespace wobble {

// A Wavefront OBJ file read as a spring network's raw material: positions, polygons as written
// (not triangulated), and per-vertex texture coordinates.
struct ObjMesh {
  Eigen::MatrixXd V;  // #V by 3 vertex positions, in the order of the `v` lines
  // 0-based polygons: every `f` element in file order (2-vertex faces included, each with at
  // least 2 distinct vertices), then every segment of every `l` polyline as a 2-vertex face.
  std::vector<std::vector<int>> faces;
  // #V by 2 texture coordinates: for each vertex the `vt` of the first face corner that gives
  // it one (vertices that none gives stay (0, 0)). Empty when no face corner has a `vt`.
  Eigen::MatrixXd uv;
};

// Read an OBJ file in one pass of Wobble's own (double precision, no triangulation). Only `v`,
// `vt`, `f` and `l` matter; other statements (groups, materials, normals, points) are ignored.
// Indices may be 1-based (a vertex may come after the face that names it) or negative (counting
// back from the latest vertex or texture coordinate before the line, as OBJ allows); normal
// indices (`v//vn`, `v/vt/vn`) are checked for form only. Coordinates are the correctly rounded
// doubles of their decimals (strtod), so a file written by write_obj reads back bit for bit.
//
// A `#` starts a comment to the end of its line, on a line of its own or after any statement
// (`f 1 2 3 # the roof`); whatever else a `v`, `vt`, `f` or `l` line holds is refused: `v` takes
// 3 to 6 numbers (x y z, x y z w, or x y z r g b; only x y z are used), `vt` 1 to 3 (u v used).
//
// A UTF-8 byte-order mark before the first line is skipped.
//
// Throws InputError, with a one-line message "PATH: line L: what, expected what" where a line
// is to blame, for: a missing or unreadable file, or one that is not a regular file or is larger
// than obj_file.max_bytes (io/input_file_limits.h); a coordinate that is not a finite number or
// underflows (1e-400); an index that is 0, malformed or out of range; a face or line of fewer
// than 2 vertices; a face of more than max_face_corners corners; faces and lines that give more
// than max_face_springs springs in all (n(n-1)/2 a face, counted before shared pairs merge); a
// face that uses a vertex twice; and a file with no vertices or with no faces and no lines.
ObjMesh read_obj(const std::string& path);

}  // namespace wobble

#endif

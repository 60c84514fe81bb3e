#ifndef WOBBLE_IO_READ_TETGEN_H
#define WOBBLE_IO_READ_TETGEN_H

#include <string>

#include "tet_mesh_file.h"

namespace wobble {

// Read a TetGen mesh: the pair BASE.node and BASE.ele. `path` may name either file or the base
// itself (a path ending in .node or .ele has that ending dropped). `#` starts a comment that
// runs to the end of its line; blank lines are skipped.
//
//   BASE.node  first line: #points dimension(3) [#attributes] [boundary markers (0 or 1)]
//              then one line per point: index x y z [attributes...] [marker]
//   BASE.ele   first line: #tetrahedra [nodes per tetrahedron (4 or 10)] [#attributes]
//              then one line per tetrahedron: index n1 n2 n3 n4 [...]
//
// Missing header fields default to 3, 0 and 0 (dimension, attributes, markers) and 4, 0 (nodes,
// attributes). The first point's index (0 or 1) sets the numbering for both files, and points
// must be numbered consecutively from it, as TetGen writes them. Of a 10-node (quadratic)
// tetrahedron only the four corners, listed first, are kept. Lines after the declared rows are
// ignored, as TetGen does; points that no tetrahedron uses are kept.
//
// A UTF-8 byte-order mark at the start of either file is skipped.
//
// Throws InputError, with a one-line message "FILE: line L: expected ..." naming the .node or
// .ele file at fault, when a file cannot be read, is not a regular file or is larger than
// tetgen_node_file.max_bytes or tetgen_ele_file.max_bytes (io/input_file_limits.h), a header
// field is out of range, a row is short or holds a malformed, non-finite or underflowing
// (1e-400) number, a file ends before its declared rows, a point
// index breaks the numbering, a tetrahedron names a point that does not exist, there is no point
// or no tetrahedron, or a tetrahedron is degenerate (a repeated corner or zero volume, its
// corners coplanar to rounding: |volume| <= 1e-12 × its longest edge³).
//
// Inputs:
//   path  BASE.node, BASE.ele or BASE
// Outputs:
//   V  #V by 3 point positions, in .node order, T  #T by 4 tetrahedra, 0-based
TetMeshFile read_tetgen(const std::string& path);

// The BASE that read_tetgen reads BASE.node and BASE.ele of, for `path`.
std::string tetgen_base(const std::string& path);

}  // namespace wobble

#endif

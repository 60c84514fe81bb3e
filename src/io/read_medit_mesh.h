#ifndef WOBBLE_IO_READ_MEDIT_MESH_H
#define WOBBLE_IO_READ_MEDIT_MESH_H

#include <string>

#include "tet_mesh_file.h"

namespace wobble {

// Read the vertices and tetrahedra of an ASCII MEDIT mesh (`.mesh`, as written by TetGen -g,
// Gmsh, MMG or CGAL). The file is a sequence of keywords, each followed by its data; words are
// separated by any whitespace, so rows may span lines, and `#` starts a comment that runs to
// the end of its line. Keywords may come in any order and are matched ignoring case:
//
//   MeshVersionFormatted v    any version (1 and 2 differ only in binary files)
//   Dimension 3               optional; any other dimension is refused
//   Vertices n                then n rows `x y z ref`
//   Tetrahedra n              then n rows `a b c d ref`, 1-based indices into Vertices
//   End                       optional; anything after it is ignored
//
// Edges, Triangles, Quadrilaterals, Hexahedra, Prisms, Pyramids, Corners, Ridges, the Required*
// lists, Normals, Tangents and the *AtVertices lists are read (count, then rows of numbers) and
// skipped. Any other keyword is refused, because without knowing its row width there is no
// telling where its data ends. Vertices that no tetrahedron uses are kept.
//
// A UTF-8 byte-order mark before the first keyword is skipped.
//
// Throws InputError, with a one-line message "PATH: line L: expected ...", when the file cannot
// be read, is not a regular file or is larger than medit_file.max_bytes (io/input_file_limits.h),
// a keyword is unknown, a number is malformed, not finite or underflows (1e-400), a section ends
// early, a section appears twice, a count is above Wobble's limits (10,000,000 vertices,
// 60,000,000 tetrahedra; sim/input_limits.h), an index is 0 or above the vertex count, there is
// no Vertices section or no tetrahedron, or a tetrahedron is degenerate: a repeated corner or
// zero volume (its corners coplanar to rounding, |volume| <= 1e-12 × its longest edge³), which
// would give its corners no mass and its faces no orientation.
//
// Inputs:
//   path  the .mesh file
// Outputs:
//   V  #V by 3 vertex positions, T  #T by 4 tetrahedra, 0-based
TetMeshFile read_medit_mesh(const std::string& path);

}  // namespace wobble

#endif

#ifndef WOBBLE_IO_TET_MESH_FILE_H
#define WOBBLE_IO_TET_MESH_FILE_H

#include <Eigen/Core>

namespace wobble {

// A tetrahedral mesh as read from a file (MEDIT .mesh, TetGen .node/.ele). The readers keep the
// file's vertex order and keep vertices that no tetrahedron uses; tetrahedra keep the file's
// corner order, so their orientation is whatever the file wrote (tet_mesh_boundary_faces orients
// by geometry, so either sign works).
struct TetMeshFile {
  Eigen::MatrixXd V;  // #V by 3 vertex positions, in the file's units (Wobble assumes metres)
  Eigen::MatrixXi T;  // #T by 4 tetrahedra, 0-based indices into rows of V
};

}  // namespace wobble

#endif

#ifndef WOBBLE_SIM_TET_MESH_H
#define WOBBLE_SIM_TET_MESH_H

#include <Eigen/Core>

namespace wobble {

// The signed volume of tetrahedron t (m³): positive when (b − a, c − a, d − a) is right-handed.
//
// Inputs:
//   V  #V by 3 list of vertex positions
//   T  #T by 4 list of tetrahedra (a, b, c, d)
double tet_signed_volume(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T, Eigen::Index t);

// Every distinct edge of a tetrahedral mesh, each once, with the smaller index first, sorted.
//
// Inputs:
//   T  #T by 4 list of tetrahedra, indices into rows of a vertex list
// Outputs:
//   #E by 2 list of edges
Eigen::MatrixXi tet_mesh_edges(const Eigen::MatrixXi& T);

// The boundary of a tetrahedral mesh: the triangles that belong to exactly one tetrahedron,
// oriented counter-clockwise seen from outside (normal pointing away from the tetrahedron).
//
// Inputs:
//   V  #V by 3 list of vertex positions (used to orient each tetrahedron)
//   T  #T by 4 list of tetrahedra
// Outputs:
//   #F by 3 list of boundary triangles
Eigen::MatrixXi tet_mesh_boundary_faces(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T);

// Lumped masses: each tetrahedron gives a quarter of its mass (density × volume) to each corner.
//
// Inputs:
//   V        #V by 3 list of vertex positions (m)
//   T        #T by 4 list of tetrahedra
//   density  kg/m³
// Outputs:
//   #V list of masses (kg)
Eigen::VectorXd tet_mesh_lumped_masses(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T,
                                       double density);

// Whether the tetrahedron (a, b, c, d) has no volume to speak of: |volume| at most 1e-12 of its
// longest edge cubed (repeated or coplanar corners). Such a tetrahedron gives its corners no mass
// and its faces no orientation, so mesh readers refuse it.
bool tetrahedron_is_flat(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c, const Eigen::Vector3d& d);

}  // namespace wobble

#endif

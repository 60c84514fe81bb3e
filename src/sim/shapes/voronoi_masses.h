#ifndef WOBBLE_SIM_VORONOI_MASSES_H
#define WOBBLE_SIM_VORONOI_MASSES_H

#include <Eigen/Core>

namespace wobble {

// Lumped mixed-Voronoi area of every vertex of a triangle mesh (Meyer et al. 2003): each
// triangle gives each of its corners the part of the triangle closer to that corner than to the
// others, computed as
//
//   A_i += (1/8)(‖x_i − x_j‖² cot θ_k + ‖x_i − x_k‖² cot θ_j)
//
// for corner i with the other corners j and k (θ_j, θ_k the angles there). When the triangle is
// obtuse that region leaves the triangle, so instead the obtuse corner gets half the triangle's
// area and the other two a quarter each. A right angle counts as not obtuse (its cotangent is 0,
// so both rules agree there). Either way each triangle hands out exactly its own area, so
// Σ A_i is the mesh's total area. A degenerate (zero-area) triangle gives nothing.
//
// The course's reference program uses these areas directly as vertex masses (1 kg per m²).
//
// Inputs:
//   V  #V by 3 list of vertex positions (m)
//   F  #F by 3 list of triangles, indices into rows of V
// Returns:
//   #V list of areas (m²); 0 for a vertex in no (non-degenerate) triangle
Eigen::VectorXd voronoi_masses(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

}  // namespace wobble

#endif

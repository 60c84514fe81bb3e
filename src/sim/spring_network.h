#ifndef WOBBLE_SIM_SPRING_NETWORK_H
#define WOBBLE_SIM_SPRING_NETWORK_H

#include <Eigen/Core>

namespace wobble {

// The rest shape of a deformable object: point masses joined by springs, plus the triangles
// that are drawn (springs and render faces are independent: a cloth has bend springs that are
// no triangle's edge, a jelly draws only its boundary), and for a solid its tetrahedra.
struct SpringNetwork {
  Eigen::MatrixXd V;  // #V by 3 rest positions (m)
  Eigen::MatrixXi E;  // #E by 2 springs, indices into rows of V
  Eigen::MatrixXi F;  // #F by 3 render triangles, counter-clockwise seen from outside; may be empty
  Eigen::VectorXd m;  // #V masses (kg)
  Eigen::MatrixXi T;  // #T by 4 tetrahedra of a solid, indices into rows of V; empty for a
                      // surface. The springs do not read it; the volume term does.
};

// Throws InputError unless the network is well formed: V is #V by 3 with every coordinate within
// limits::coordinate, every index in E, F and T is in range, no spring joins a vertex to itself,
// and every mass is within limits::vertex_mass (sim/value_limits.h).
void validate_spring_network(const SpringNetwork& network);

}  // namespace wobble

#endif

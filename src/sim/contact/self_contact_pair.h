#ifndef WOBBLE_SIM_CONTACT_SELF_CONTACT_PAIR_H
#define WOBBLE_SIM_CONTACT_SELF_CONTACT_PAIR_H

#include <Eigen/Core>

namespace wobble {

// Two features of a surface near each other: a vertex and a triangle, or two edges. Their
// closest points at the start of an epoch give q = Σ βₖ x_{vertex[k]} (β = 1, −α for a vertex and
// a triangle's barycentric α; 1−s, s, −(1−u), −u for two edges), and self-contact keeps
// q·normal ≥ target (see self_contact_proximity.h for how each field is filled).
struct SelfContactPair {
  int vertex[4];
  double beta[4];
  Eigen::Vector3d normal;
  double target = 0.0;  // m: the gap to keep
  double depth = 0.0;   // m: the distance ‖q‖ where the pair was found
  bool vertex_triangle = true;
};

}  // namespace wobble

#endif

#ifndef WOBBLE_SIM_CONTACT_SELF_COLLISION_H
#define WOBBLE_SIM_CONTACT_SELF_COLLISION_H

#include <Eigen/Core>

#include "sim/spring_network.h"

namespace wobble {

// Self-collision as a scene or the user sets it up. Off unless asked for (never on for the
// course's scenes).
struct SelfCollisionParams {
  bool on = false;
  double thickness = 0.01;  // m: the gap the surface keeps between its own layers
};

// Throws InputError unless the thickness is within limits::self_collision_thickness.
void validate_self_collision(const SelfCollisionParams& params);

// The largest thickness a mesh's surface can keep (m): 1.5 times its mean rest edge (at least
// limits::self_collision_thickness.low). A thicker gap than that would have to hold apart the
// surface's own neighbours across several edges, which its rest shape puts closer; the
// thickness used is clamped to it, and the caller says so.
double largest_self_collision_thickness(const SpringNetwork& network);
// The same from the surface's mean rest edge (m).
double largest_self_collision_thickness(double mean_edge);
// The largest thickness, in mean rest edges.
constexpr double largest_thickness_in_edges = 1.5;

}  // namespace wobble

#endif

#include "sim/contact/self_collision.h"

#include <algorithm>

#include "sim/contact/self_collision_surface.h"
#include "sim/input_error.h"
#include "sim/value_limits.h"

namespace wobble {

void validate_self_collision(const SelfCollisionParams& params) {
  if (!limits::self_collision_thickness.contains(params.thickness)) {
    throw InputError("self-collision thickness: expected " +
                     expected_in(limits::self_collision_thickness) + ", got " +
                     limit_text(params.thickness));
  }
}

double largest_self_collision_thickness(double mean_edge) {
  return std::max(limits::self_collision_thickness.low, largest_thickness_in_edges * mean_edge);
}

double largest_self_collision_thickness(const SpringNetwork& network) {
  return largest_self_collision_thickness(SelfCollisionSurface(network).mean_edge);
}

}  // namespace wobble

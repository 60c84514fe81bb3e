#ifndef WOBBLE_IO_SHAPE_LIMITS_H
#define WOBBLE_IO_SHAPE_LIMITS_H

#include <nlohmann/json.hpp>
#include <string>

#include "sim/spring_network.h"

namespace wobble {

// Throws InputError unless every vertex of a Wobble scene's shape is within limits::coordinate
// and every mass within limits::vertex_mass (sim/value_limits.h). Each key may be within its own
// limits and still give, with the others, masses that underflow (a tiny mesh.scale) or a mesh
// out of range, so the message names the keys of `object` (the scene at `path`) that set them:
// "scene.json: material.mass and mesh.resolution: vertex masses from 2.55e-11 to ...".
void check_shape_limits(const std::string& path, const nlohmann::json& object,
                        const SpringNetwork& network);

}  // namespace wobble

#endif

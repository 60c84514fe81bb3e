#ifndef WOBBLE_SIM_BUILTIN_SCENES_H
#define WOBBLE_SIM_BUILTIN_SCENES_H

#include <string>
#include <vector>

#include "sim/scene.h"

namespace wobble {

// Names of the scenes Wobble generates itself, in the order a scene picker lists them.
std::vector<std::string> builtin_scene_names();

// Build a built-in scene:
//   cloth  40×40 vertices, 1 m square, 0.25 kg/m², structural + shear + bend springs, lying
//          flat 1.2 m above the ground and hanging from its two top corners
//   jelly  0.5 m cube of 8³ cells (6 tetrahedra each), 200 kg/m³, base pinned on the ground,
//          set swaying by an initial sideways velocity that grows with height
// Gravity is m·g with g = 9.81 m/s² down y. Throws InputError for an unknown name, listing the
// known ones.
Scene make_builtin_scene(const std::string& name);

}  // namespace wobble

#endif

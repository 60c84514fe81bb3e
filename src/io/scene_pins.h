#ifndef WOBBLE_IO_SCENE_PINS_H
#define WOBBLE_IO_SCENE_PINS_H

#include <Eigen/Core>
#include <string>
#include <vector>

#include "io/json_fields.h"

namespace wobble {

// The vertices whose rest height is within a millionth of the shape's size of the highest
// (extreme = +1) or lowest (extreme = −1).
//   V  #V by 3 rest positions
std::vector<int> extreme_vertices(const Eigen::MatrixXd& V, int extreme);

// The pins a scene file asks for at `key`: a vertex index (0-based), a named selection, a height
// band, or a list of these. Selections: "top" and "bottom" (extreme_vertices) on any shape;
// "top-edge", "top-corners", "corners" and "left-edge" on the cloth generator (cloth_resolution >
// 0, row 0 is the top edge). Bands: {"below": h} pins every vertex within h metres of the lowest,
// {"above": h} of the highest (for rounded shapes). Returns sorted, distinct indices. Throws
// InputError naming the file and key.
std::vector<int> scene_pins(JsonFields& fields, const std::string& key, const Eigen::MatrixXd& V,
                            int cloth_resolution);

}  // namespace wobble

#endif

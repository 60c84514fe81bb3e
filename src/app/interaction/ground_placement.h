#ifndef WOBBLE_APP_INTERACTION_GROUND_PLACEMENT_H
#define WOBBLE_APP_INTERACTION_GROUND_PLACEMENT_H

#include <Eigen/Core>
#include <vector>

#include "sim/contact/collider.h"

namespace wobble {

// How far below the lowest point a scene reaches the grid is drawn, as a share of the rest
// shape's largest extent: far enough that hanging cloth does not touch the lines.
inline constexpr double ground_margin_share = 0.03;
// How much longer than at rest a path of springs is taken to stretch under its own weight.
inline constexpr double hanging_stretch = 1.1;

// The height (m) of the ground grid, below anything the scene reaches:
//   - with a ground collider, its height (the highest one, if several);
//   - with pins, the lowest a vertex can hang: for each vertex reached from a pin through the
//     springs, max over pins of (pin_y − 1.1·d), d the shortest path along the springs at rest
//     (never shorter than the straight line, and right for folded shapes such as a shirt),
//     then the minimum over vertices, never above the rest minimum, less the margin;
//   - without pins, the rest minimum less the margin.
//   V     #V by 3 rest positions (m)
//   E     #E by 2 spring end indices into rows of V
//   pins  indices of pinned vertices
double ground_grid_height(const Eigen::MatrixXd& V, const Eigen::MatrixXi& E,
                          const std::vector<int>& pins, const std::vector<Collider>& colliders);

}  // namespace wobble

#endif

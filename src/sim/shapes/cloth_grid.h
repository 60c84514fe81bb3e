#ifndef WOBBLE_SIM_CLOTH_GRID_H
#define WOBBLE_SIM_CLOTH_GRID_H

#include "sim/spring_network.h"

namespace wobble {

struct ClothGridOptions {
  int resolution = 40;          // vertices along each side, >= 2
  double size = 1.0;            // side length (m)
  double areal_density = 0.25;  // kg/m²
  bool structural = true;       // springs to the 4 grid neighbours
  bool shear = true;            // springs along both diagonals of every cell
  bool bend = true;             // springs to the vertices two apart along rows and columns
};

// A square cloth of resolution × resolution vertices lying flat in the y = 0 plane, centred on
// the origin: vertex (row, column) has index row·resolution + column and sits at
// x = −size/2 + column·h, z = −size/2 + row·h, with h = size/(resolution − 1). Row 0 is the
// "top" edge (smallest z); its two ends are the top corners.
//
// Render faces are two triangles per cell, facing +y. Each cell gives a quarter of its mass
// (areal_density × h²) to each corner, so masses are symmetric under mirroring the grid.
// Throws InputError for resolution < 2 or a non-positive size or density.
SpringNetwork make_cloth_grid(const ClothGridOptions& options);

// Index of the vertex at (row, column) of a cloth grid made with this resolution.
inline int cloth_grid_vertex(int resolution, int row, int column) {
  return row * resolution + column;
}

}  // namespace wobble

#endif

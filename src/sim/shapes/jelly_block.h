#ifndef WOBBLE_SIM_JELLY_BLOCK_H
#define WOBBLE_SIM_JELLY_BLOCK_H

#include "sim/spring_network.h"

namespace wobble {

struct JellyBlockOptions {
  int resolution = 8;      // cells along each side, >= 1
  double size = 0.5;       // side length (m)
  double density = 200.0;  // kg/m³
};

// A cube of resolution³ cells, each split into 6 tetrahedra around its main diagonal (the
// Freudenthal–Kuhn split, which matches across neighbouring cells). The cube spans
// [−size/2, size/2] in x and z and [0, size] in y, so it stands on the y = 0 plane. Vertex
// (i, j, k) along (x, y, z) has index (j·(res+1) + k)·(res+1) + i; the bottom face (j = 0)
// holds the first (res+1)² vertices.
//
// Springs are the tetrahedra's edges; render faces are the boundary triangles facing outward;
// each tetrahedron gives a quarter of its mass (density × volume) to each corner. The network's
// T holds the tetrahedra.
// Throws InputError for resolution < 1 or a non-positive size or density.
//
// Outputs (besides the returned network):
//   T  #T by 4 list of tetrahedra, if not null
SpringNetwork make_jelly_block(const JellyBlockOptions& options, Eigen::MatrixXi* T = nullptr);

}  // namespace wobble

#endif

#include "jelly_block.h"

#include <algorithm>
#include <array>
#include <string>

#include "sim/input_error.h"
#include "tet_mesh.h"

namespace wobble {

SpringNetwork make_jelly_block(const JellyBlockOptions& options, Eigen::MatrixXi* T_out) {
  const int cells = options.resolution;
  if (cells < 1)
    throw InputError("jelly resolution must be at least 1, got " + std::to_string(cells));
  if (!(options.size > 0.0)) throw InputError("jelly size must be positive");
  if (!(options.density > 0.0)) throw InputError("jelly density must be positive");
  const int n = cells + 1;
  const double h = options.size / cells;
  const auto index = [n](int i, int j, int k) { return (j * n + k) * n + i; };

  SpringNetwork jelly;
  jelly.V.resize(n * n * n, 3);
  for (int j = 0; j < n; ++j) {
    for (int k = 0; k < n; ++k) {
      for (int i = 0; i < n; ++i) {
        jelly.V.row(index(i, j, k)) << -0.5 * options.size + i * h, j * h,
            -0.5 * options.size + k * h;
      }
    }
  }

  // Each of the 6 orders in which the three axes can be stepped gives one tetrahedron: the walk
  // from corner (0,0,0) to (1,1,1) along the cell's edges in that order.
  std::array<int, 3> axes = {0, 1, 2};
  Eigen::MatrixXi T(6 * cells * cells * cells, 4);
  int t = 0;
  for (int j = 0; j < cells; ++j) {
    for (int k = 0; k < cells; ++k) {
      for (int i = 0; i < cells; ++i) {
        std::sort(axes.begin(), axes.end());
        do {
          std::array<int, 3> corner = {i, j, k};
          T(t, 0) = index(corner[0], corner[1], corner[2]);
          for (int step = 0; step < 3; ++step) {
            ++corner[axes[step]];
            T(t, step + 1) = index(corner[0], corner[1], corner[2]);
          }
          ++t;
        } while (std::next_permutation(axes.begin(), axes.end()));
      }
    }
  }

  jelly.E = tet_mesh_edges(T);
  jelly.F = tet_mesh_boundary_faces(jelly.V, T);
  jelly.m = tet_mesh_lumped_masses(jelly.V, T, options.density);
  if (T_out) *T_out = T;
  jelly.T = std::move(T);
  return jelly;
}

}  // namespace wobble

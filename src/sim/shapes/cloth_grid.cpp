#include "cloth_grid.h"

#include <string>
#include <vector>

#include "sim/input_error.h"

namespace wobble {

SpringNetwork make_cloth_grid(const ClothGridOptions& options) {
  const int n = options.resolution;
  if (n < 2) throw InputError("cloth resolution must be at least 2, got " + std::to_string(n));
  if (!(options.size > 0.0)) throw InputError("cloth size must be positive");
  if (!(options.areal_density > 0.0)) throw InputError("cloth areal density must be positive");
  const double h = options.size / (n - 1);
  const auto index = [n](int row, int column) { return cloth_grid_vertex(n, row, column); };

  SpringNetwork cloth;
  cloth.V.resize(n * n, 3);
  for (int row = 0; row < n; ++row) {
    for (int column = 0; column < n; ++column) {
      cloth.V.row(index(row, column)) << -0.5 * options.size + column * h, 0.0,
          -0.5 * options.size + row * h;
    }
  }

  std::vector<Eigen::Vector2i> springs;
  const auto add = [&](int row, int column, int other_row, int other_column) {
    if (other_row < n && other_column >= 0 && other_column < n) {
      springs.emplace_back(index(row, column), index(other_row, other_column));
    }
  };
  for (int row = 0; row < n; ++row) {
    for (int column = 0; column < n; ++column) {
      if (options.structural) {
        add(row, column, row, column + 1);
        add(row, column, row + 1, column);
      }
      if (options.shear) {
        add(row, column, row + 1, column + 1);
        add(row, column, row + 1, column - 1);
      }
      if (options.bend) {
        add(row, column, row, column + 2);
        add(row, column, row + 2, column);
      }
    }
  }
  cloth.E.resize(springs.size(), 2);
  for (std::size_t e = 0; e < springs.size(); ++e)
    cloth.E.row(e) = springs[e].transpose();

  cloth.F.resize(2 * (n - 1) * (n - 1), 3);
  cloth.m = Eigen::VectorXd::Zero(n * n);
  const double corner_mass = options.areal_density * h * h / 4.0;
  int face = 0;
  for (int row = 0; row + 1 < n; ++row) {
    for (int column = 0; column + 1 < n; ++column) {
      const int a = index(row, column), b = index(row, column + 1);
      const int c = index(row + 1, column), d = index(row + 1, column + 1);
      // (a, c, b) and (b, c, d) are counter-clockwise seen from +y.
      cloth.F.row(face++) << a, c, b;
      cloth.F.row(face++) << b, c, d;
      for (int corner : {a, b, c, d})
        cloth.m(corner) += corner_mass;
    }
  }
  return cloth;
}

}  // namespace wobble

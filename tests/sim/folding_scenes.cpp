#include "folding_scenes.h"

#include <algorithm>
#include <cmath>

#include "sim/shapes/cloth_grid.h"
#include "test_colliders.h"

namespace wobble::testing {

namespace {

constexpr double pi = 3.14159265358979323846;

SimulationParams folding_params(const SelfCollisionParams& self_collision) {
  SimulationParams params;
  params.k = 1000.0;
  params.dt = 1.0 / 60.0;
  params.iterations = 30;
  params.damping = 0.05;
  params.contact.friction = 0.4;
  params.self_collision = self_collision;
  return params;
}

// 0 → 1 with zero speed at both ends, so a dragged pin starts and stops without a jerk.
double ease(double s) {
  s = std::clamp(s, 0.0, 1.0);
  return s * s * (3.0 - 2.0 * s);
}

}  // namespace

FoldingScene cloth_pile_scene(const SelfCollisionParams& self_collision) {
  FoldingScene scene;
  scene.name = "cloth pile";
  const int n = 32;
  ClothGridOptions options;
  options.resolution = n;
  // A soft cloth (no bend springs): a pile keeps its folds instead of springing flat.
  options.bend = false;
  scene.network = make_cloth_grid(options);
  Eigen::MatrixXd& V = scene.network.V;
  // Upright in the x–y plane: row 0 on top at y = 1.03, the last row 3 cm above the ground.
  const Eigen::VectorXd z = V.col(2);
  V.col(1) = (0.53 - z.array()).matrix();
  V.col(2).setZero();
  scene.initial_velocity = Eigen::MatrixXd::Zero(V.rows(), 3);
  for (Eigen::Index i = 0; i < V.rows(); ++i) {
    const double x = V(i, 0), y = V(i, 1);
    scene.initial_velocity(i, 2) = 1.2 * y * std::sin(3.0 * pi * x + 0.5);
    scene.initial_velocity(i, 0) = 0.3 * y * std::cos(2.0 * pi * x);
  }
  scene.params = folding_params(self_collision);
  scene.params.contact.colliders = {ground_collider()};
  scene.steps = 300;
  scene.before_step = [](Simulation&, int) {};
  return scene;
}

FoldingScene dragged_across_scene(const SelfCollisionParams& self_collision) {
  FoldingScene scene;
  scene.name = "dragged across";
  const int n = 32;
  ClothGridOptions options;
  options.resolution = n;
  scene.network = make_cloth_grid(options);
  // The cloth lies over a low bump (a capsule across it, 2 cm high), where the fold comes down:
  // without self-collision the folded half falls through the raised half under it. On a flat
  // floor both halves come to rest at the same height, and nothing tells crossing from lying on.
  scene.network.V.col(1).array() += 0.035;
  for (int column = 0; column < n; ++column)
    scene.pins.push_back(cloth_grid_vertex(n, 0, column));
  scene.params = folding_params(self_collision);
  const double bump = 0.04;
  scene.params.contact.colliders = {
      ground_collider(), capsule_collider(Eigen::Vector3d(-1.0, 0.02 - bump, 0.25),
                                          Eigen::Vector3d(1.0, 0.02 - bump, 0.25), bump)};
  const int drag_steps = 120;
  scene.steps = drag_steps + 60;
  const std::vector<int> pins = scene.pins;
  const Eigen::MatrixXd rest = scene.network.V;
  scene.before_step = [pins, rest, drag_steps](Simulation& simulation, int step) {
    // A half circle in the y–z plane from z = −0.5 over the cloth to z = +0.55, raised by 2 cm
    // along the way: the edge comes down 5.5 cm above the ground just past the opposite edge.
    const double progress = ease(static_cast<double>(step + 1) / drag_steps);
    const double angle = pi * progress;
    const double radius = 0.525, centre = 0.025;
    const double y = rest(0, 1) + 0.02 * progress + radius * std::sin(angle);
    const double z = centre - radius * std::cos(angle);
    for (int i : pins)
      simulation.set_pin_target(i, Eigen::Vector3d(rest(i, 0), y, z));
  };
  return scene;
}

FoldingScene sphere_wrap_scene(const SelfCollisionParams& self_collision) {
  FoldingScene scene;
  scene.name = "sphere wrap";
  const int width = 8, length = 80;
  const double size = 2.6;
  const double h = size / (length - 1);
  // The first 8 rows of an 80 × 80 grid: rows across the strip, columns along it.
  ClothGridOptions options;
  options.resolution = length;
  options.size = size;
  const SpringNetwork grid = make_cloth_grid(options);
  const int kept = width * length;  // vertices of rows 0..7 are exactly 0..kept−1
  SpringNetwork& strip = scene.network;
  const auto keep = [kept](const Eigen::MatrixXi& M) {
    std::vector<Eigen::Index> rows;
    for (Eigen::Index r = 0; r < M.rows(); ++r) {
      if ((M.row(r).array() < kept).all()) rows.push_back(r);
    }
    Eigen::MatrixXi out(static_cast<Eigen::Index>(rows.size()), M.cols());
    for (std::size_t r = 0; r < rows.size(); ++r)
      out.row(static_cast<Eigen::Index>(r)) = M.row(rows[r]);
    return out;
  };
  strip.E = keep(grid.E);
  strip.F = keep(grid.F);
  // Masses again from the strip's own cells (the grid gave its last row a share of the cells
  // beyond it).
  strip.m = Eigen::VectorXd::Zero(kept);
  const double corner_mass = options.areal_density * h * h / 4.0;
  for (int row = 0; row + 1 < width; ++row) {
    for (int column = 0; column + 1 < length; ++column) {
      for (int dr : {0, 1})
        for (int dc : {0, 1})
          strip.m(cloth_grid_vertex(length, row + dr, column + dc)) += corner_mass;
    }
  }
  // Hanging straight down beside the sphere from its pinned end (column 0).
  const Eigen::Vector3d centre(0.0, 3.0, 0.0);
  const double sphere_radius = 0.2, pin_radius = 0.26;
  strip.V.resize(kept, 3);
  for (int row = 0; row < width; ++row) {
    for (int column = 0; column < length; ++column) {
      strip.V.row(cloth_grid_vertex(length, row, column)) =
          (centre + Eigen::Vector3d(pin_radius, -column * h, (row - 0.5 * (width - 1)) * h))
              .transpose();
    }
    scene.pins.push_back(cloth_grid_vertex(length, row, 0));
  }
  scene.params = folding_params(self_collision);
  scene.params.contact.colliders = {sphere_collider(centre, sphere_radius)};
  // Wobble's default iterations: at 30 the strip stretches and sags into the pin's path, and the
  // pin (which goes where it is told) is dragged through it.
  scene.params.iterations = 50;
  const int wind_steps = 480;
  scene.steps = wind_steps + 60;
  const std::vector<int> pins = scene.pins;
  const Eigen::MatrixXd rest = strip.V;
  scene.before_step = [=](Simulation& simulation, int step) {
    const double angle = 4.0 * pi * ease(static_cast<double>(step + 1) / wind_steps);
    for (int i : pins) {
      const Eigen::Vector3d target =
          centre + Eigen::Vector3d(pin_radius * std::cos(angle), pin_radius * std::sin(angle),
                                   rest(i, 2) - centre(2));
      simulation.set_pin_target(i, target);
    }
  };
  return scene;
}

}  // namespace wobble::testing

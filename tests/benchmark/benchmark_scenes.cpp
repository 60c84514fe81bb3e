#include "benchmark_scenes.h"

#include <stdexcept>

#include "sim/seed/fast_mass_springs_precomputation_sparse.h"
#include "sim/shapes/builtin_scenes.h"
#include "sim/shapes/cloth_grid.h"

namespace wobble::benchmark {

namespace {

Scene hanging_cloth(int resolution, double size) {
  ClothGridOptions options;
  options.resolution = resolution;
  options.size = size;
  Scene scene;
  scene.network = make_cloth_grid(options);
  scene.network.V.col(1).array() += 1.2;
  scene.pins = {cloth_grid_vertex(resolution, 0, 0),
                cloth_grid_vertex(resolution, 0, resolution - 1)};
  scene.params.k = 400.0;
  scene.params.dt = 1.0 / 60.0;
  return scene;
}

}  // namespace

const std::vector<BenchmarkScene>& benchmark_scenes() {
  static const std::vector<BenchmarkScene> scenes = {
      {"curtain 81x81", hanging_cloth(81, 2.0)},
      {"cloth 128x128", hanging_cloth(128, 2.0)},
      {"cloth 256x256", hanging_cloth(256, 4.0)},
      {"jelly (built-in)", make_builtin_scene("jelly")},
  };
  return scenes;
}

ReferenceStepper::ReferenceStepper(const Scene& scene) : scene_(scene) {
  const SpringNetwork& network = scene.network;
  Eigen::VectorXi b(scene.pins.size());
  for (std::size_t i = 0; i < scene.pins.size(); ++i)
    b(i) = scene.pins[i];
  if (!fast_mass_springs_precomputation_sparse(network.V, network.E, scene.params.k, network.m, b,
                                               scene.params.dt, r_, M_, A_, C_,
                                               prefactorization_)) {
    throw std::runtime_error("the reference precomputation failed");
  }
  fext_ = network.m * scene.params.gravity.transpose();
  current_ = previous_ = network.V;
}

void ReferenceStepper::step(int iterations) {
  const Eigen::MatrixXd& V = scene_.network.V;
  const Eigen::MatrixXi& E = scene_.network.E;
  const double k = scene_.params.k, dt = scene_.params.dt, w = 1e10;
  const Eigen::MatrixXd y =
      M_ * (2.0 * current_ - previous_) / (dt * dt) + fext_ + w * (C_.transpose() * (C_ * V));
  next_ = current_;
  Eigen::MatrixXd d(E.rows(), 3);
  for (int iteration = 0; iteration < iterations; ++iteration) {
    for (Eigen::Index e = 0; e < E.rows(); ++e) {
      d.row(e) = r_(e) * (next_.row(E(e, 0)) - next_.row(E(e, 1))).normalized();
    }
    next_ = prefactorization_.solve(k * (A_.transpose() * d) + y);
  }
  previous_.swap(current_);
  current_.swap(next_);
}

}  // namespace wobble::benchmark

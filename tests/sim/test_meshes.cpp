#include "test_meshes.h"

#include "sim/shapes/cloth_grid.h"
#include "sim/shapes/jelly_block.h"

namespace wobble::testing {

SimulationParams test_params() {
  SimulationParams params;
  params.k = 200.0;
  params.dt = 1.0 / 60.0;
  params.iterations = 50;
  return params;
}

TestMesh chain_mesh(int links) {
  TestMesh mesh;
  mesh.name = "chain";
  mesh.network.V = Eigen::MatrixXd::Zero(links + 1, 3);
  mesh.network.E.resize(links, 2);
  for (int i = 0; i <= links; ++i)
    mesh.network.V(i, 0) = 0.1 * i;
  for (int e = 0; e < links; ++e)
    mesh.network.E.row(e) << e, e + 1;
  mesh.network.m = Eigen::VectorXd::Constant(links + 1, 0.05);
  mesh.pins = {0};
  return mesh;
}

TestMesh grid_mesh() {
  ClothGridOptions options;
  options.resolution = 6;
  TestMesh mesh{"grid", make_cloth_grid(options), {0, options.resolution - 1}};
  return mesh;
}

TestMesh tet_block_mesh() {
  JellyBlockOptions options;
  options.resolution = 2;
  TestMesh mesh{"tet_block", make_jelly_block(options), {}};
  for (Eigen::Index i = 0; i < mesh.network.V.rows(); ++i) {
    if (mesh.network.V(i, 1) == 0.0) mesh.pins.push_back(static_cast<int>(i));
  }
  return mesh;
}

std::vector<TestMesh> all_test_meshes() {
  return {chain_mesh(5), grid_mesh(), tet_block_mesh()};
}

Eigen::MatrixXd gravity_forces(const Eigen::VectorXd& m) {
  return m * Eigen::RowVector3d(0.0, -9.81, 0.0);
}

Eigen::VectorXi pin_vector(const std::vector<int>& pins) {
  Eigen::VectorXi b(pins.size());
  for (std::size_t c = 0; c < pins.size(); ++c)
    b(c) = pins[c];
  return b;
}

}  // namespace wobble::testing

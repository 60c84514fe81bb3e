#ifndef WOBBLE_TESTS_SIM_TEST_MESHES_H
#define WOBBLE_TESTS_SIM_TEST_MESHES_H

#include <Eigen/Core>
#include <string>
#include <vector>

#include "sim/simulation.h"
#include "sim/spring_network.h"

namespace wobble::testing {

// A small spring network with its pins, for tests that run the same thing on several shapes.
struct TestMesh {
  std::string name;
  SpringNetwork network;
  std::vector<int> pins;
};

// `links` springs in a row along x, 0.1 m each, 0.05 kg per vertex, the first vertex pinned.
TestMesh chain_mesh(int links);
// A 6×6 cloth grid (structural, shear, bend springs) pinned at its two top corners.
TestMesh grid_mesh();
// A 2×2×2-cell tetrahedral block pinned at its base.
TestMesh tet_block_mesh();
// The three above.
std::vector<TestMesh> all_test_meshes();

// The parameters the simulation tests share: k = 200 N/m, dt = 1/60 s, 50 iterations, gravity
// 9.81 m/s² down y.
SimulationParams test_params();

// f_ext = m g with g = 9.81 m/s² down y: #V by 3.
Eigen::MatrixXd gravity_forces(const Eigen::VectorXd& m);
// The pins as the seed functions take them.
Eigen::VectorXi pin_vector(const std::vector<int>& pins);

}  // namespace wobble::testing

#endif

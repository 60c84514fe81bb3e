#ifndef WOBBLE_CHECK_CHECK_SCENE_H
#define WOBBLE_CHECK_CHECK_SCENE_H

#include <Eigen/Core>
#include <string>
#include <vector>

// One input the checker hands to a student's function and to the reference alike: a spring
// network with its parameters and a starting state. Units: metres, kilograms, seconds, newtons.
struct CheckScene {
  std::string description;  // how a FAIL line names it, e.g. "a 2-vertex spring, no pins"
  Eigen::MatrixXd V;        // #V by 3 rest positions (also the pin targets)
  Eigen::MatrixXi E;        // #E by 2 spring indices into rows of V
  double k = 0;             // stiffness (N/m)
  Eigen::VectorXd m;        // #V masses (kg), all positive
  Eigen::VectorXi b;        // #b pinned vertex indices into rows of V
  double delta_t = 0;       // time step (s)
  Eigen::MatrixXd fext;     // #V by 3 external forces (N)
  Eigen::MatrixXd Uprev;    // #V by 3 positions one step before the first step
  Eigen::MatrixXd Ucur;     // #V by 3 positions at the first step
  int steps = 1;            // how many consecutive steps a step check compares
  bool large = false;       // the scale check: only the sparse functions get it
  // Set on a copy of a scene: the outputs are passed in already holding values of their final
  // shape, so a function that only resizes them and adds into them is caught.
  bool outputs_prefilled = false;
};

// The length of the diagonal of the box around V and Ucur (m): the unit of the checker's
// tolerances on positions and lengths.
double scene_size(const CheckScene& scene);

// The generated scenes, smallest first: single springs, the seed's example E = [0 1; 1 2; 2 3],
// chains and small cloth grids, pinned and unpinned, and a stiff chain (k = 1e6 N/m, 1 kg, dt =
// 0.01 s) where 50 iterations are far from converged, so one iteration more or less shows.
std::vector<CheckScene> generated_scenes();

// A chain of `vertex_count` vertices along x, pinned at its first vertex, hanging under gravity:
// the scale check of the sparse functions (a dense #V by #V matrix of it does not fit in a
// check's memory).
CheckScene large_chain(int vertex_count);

// Gravity: (0, -9.8 m/s² · m_i, 0) on every vertex.
Eigen::MatrixXd gravity_forces(const Eigen::VectorXd& m);

#endif

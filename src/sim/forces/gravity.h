#ifndef WOBBLE_SIM_FORCES_GRAVITY_H
#define WOBBLE_SIM_FORCES_GRAVITY_H

#include <Eigen/Core>

namespace wobble {

// How gravity becomes the external force f_ext on vertex i.
enum class GravityModel {
  acceleration,      // f_i = m_i g: physical weight (Wobble's built-in scenes)
  force_per_vertex,  // f_i = g whatever the mass (what the course's reference program applies)
};

// Gravity's share of f_ext, #V by 3 (N): row i is m_i gᵀ or gᵀ as `model` says.
//   m  #V masses (kg);  g  m/s² (acceleration) or N (force_per_vertex)
// It is the base every step's f_ext starts from; the registered forces add to it.
Eigen::MatrixXd gravity_forces(const Eigen::VectorXd& m, const Eigen::Vector3d& g,
                               GravityModel model);

}  // namespace wobble

#endif

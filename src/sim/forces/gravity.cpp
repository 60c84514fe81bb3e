#include "gravity.h"

namespace wobble {

Eigen::MatrixXd gravity_forces(const Eigen::VectorXd& m, const Eigen::Vector3d& gravity,
                               GravityModel model) {
  const Eigen::RowVector3d g = gravity.transpose();
  if (model == GravityModel::acceleration) return m * g;
  return g.replicate(m.size(), 1);
}

}  // namespace wobble

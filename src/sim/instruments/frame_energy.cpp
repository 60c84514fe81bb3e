#include "sim/instruments/frame_energy.h"

namespace wobble {

FrameEnergy frame_energy(const SpringNetwork& network, const Eigen::VectorXd& r, double k,
                         double dt, const Eigen::MatrixXd& p, const Eigen::MatrixXd& previous,
                         const Eigen::MatrixXd& gravity_forces) {
  FrameEnergy energy;
  for (Eigen::Index i = 0; i < p.rows(); ++i) {
    energy.kinetic += network.m(i) * (p.row(i) - previous.row(i)).squaredNorm();
  }
  energy.kinetic *= 0.5 / (dt * dt);
  for (Eigen::Index e = 0; e < network.E.rows(); ++e) {
    const double stretch = (p.row(network.E(e, 0)) - p.row(network.E(e, 1))).norm() - r(e);
    energy.spring += stretch * stretch;
  }
  energy.spring *= 0.5 * k;
  energy.gravity = -(p.array() * gravity_forces.array()).sum();
  energy.potential = energy.spring + energy.gravity;
  energy.total = energy.kinetic + energy.potential;
  return energy;
}

}  // namespace wobble

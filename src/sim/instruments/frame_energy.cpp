#include "frame_energy.h"

#include "sim/simulation.h"

namespace wobble {

FrameEnergy frame_energy(const Simulation& simulation) {
  const Eigen::MatrixXd& p = simulation.positions();
  const Eigen::MatrixXd& previous = simulation.previous_positions();
  const SpringNetwork& network = simulation.rest();
  const Eigen::VectorXd& r = simulation.rest_lengths();
  const double dt = simulation.params().dt;
  FrameEnergy energy;
  for (Eigen::Index i = 0; i < p.rows(); ++i) {
    energy.kinetic += network.m(i) * (p.row(i) - previous.row(i)).squaredNorm();
  }
  energy.kinetic *= 0.5 / (dt * dt);
  for (Eigen::Index e = 0; e < network.E.rows(); ++e) {
    const double stretch = (p.row(network.E(e, 0)) - p.row(network.E(e, 1))).norm() - r(e);
    energy.spring += stretch * stretch;
  }
  energy.spring *= 0.5 * simulation.params().k;
  energy.gravity = -(p.array() * simulation.gravity_forces().array()).sum();
  energy.potential = energy.spring + energy.gravity;
  energy.total = energy.kinetic + energy.potential;
  return energy;
}

}  // namespace wobble

#ifndef WOBBLE_SIM_INSTRUMENTS_FRAME_ENERGY_H
#define WOBBLE_SIM_INSTRUMENTS_FRAME_ENERGY_H

#include <Eigen/Core>

#include "sim/spring_network.h"

namespace wobble {

// The mechanical energy of the simulation's current state, in J.
struct FrameEnergy {
  double kinetic = 0.0;    // ½ Σ mᵢ‖vᵢ‖², vᵢ = (pᵢᵗ − pᵢᵗ⁻ᐞᵗ)/Δt
  double spring = 0.0;     // ½k Σ(‖pᵢ−pⱼ‖−rᵢⱼ)²
  double gravity = 0.0;    // −Σ gᵢ·pᵢ, gᵢ the gravity force on vertex i (N)
  double potential = 0.0;  // spring + gravity
  double total = 0.0;      // kinetic + potential
};

// The energy of a state: positions p = `current` and `previous` (#V by 3, m) a step of `dt` (s)
// apart, of `rest` with rest lengths r (#E, m) and stiffness `k` (N/m), under the gravity forces
// g (#V by 3, N); Simulation's frame_energy(simulation) gives its own. Gravity's potential is
// measured from the world origin: with the default gravity (0, −9.81, 0) m/s² it is Σ mᵢ 9.81 yᵢ,
// zero at height y = 0 (where the built-in scenes put the ground). Wind, damping, contact and the
// pins' pull add or remove energy the sum does not account for; without them, a converged step
// keeps the total nearly constant and a fixed iteration count shows as a slow loss (the method's
// numerical damping).
FrameEnergy frame_energy(const SpringNetwork& rest, const Eigen::VectorXd& rest_lengths, double k,
                         double dt, const Eigen::MatrixXd& current, const Eigen::MatrixXd& previous,
                         const Eigen::MatrixXd& gravity_forces);

}  // namespace wobble

#endif

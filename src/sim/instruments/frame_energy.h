#ifndef WOBBLE_SIM_INSTRUMENTS_FRAME_ENERGY_H
#define WOBBLE_SIM_INSTRUMENTS_FRAME_ENERGY_H

namespace wobble {

class Simulation;

// The mechanical energy of the simulation's current state, in J.
struct FrameEnergy {
  double kinetic = 0.0;    // ½ Σ mᵢ‖vᵢ‖², vᵢ = (pᵢᵗ − pᵢᵗ⁻ᐞᵗ)/Δt
  double spring = 0.0;     // ½k Σ(‖pᵢ−pⱼ‖−rᵢⱼ)²
  double gravity = 0.0;    // −Σ gᵢ·pᵢ, gᵢ the gravity force on vertex i (N)
  double potential = 0.0;  // spring + gravity
  double total = 0.0;      // kinetic + potential
};

// The energy of `simulation` now. Gravity's potential is measured from the world origin: with the
// default gravity (0, −9.81, 0) m/s² it is Σ mᵢ 9.81 yᵢ, zero at height y = 0 (where the
// built-in scenes put the ground). Wind, damping, contact and the pins' pull add or remove energy
// the sum does not account for; without them, a converged step keeps the total nearly constant
// and a fixed iteration count shows as a slow loss (the method's numerical damping).
FrameEnergy frame_energy(const Simulation& simulation);

}  // namespace wobble

#endif

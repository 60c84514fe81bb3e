#ifndef WOBBLE_SIM_FORCES_FORCE_REGISTRY_H
#define WOBBLE_SIM_FORCES_FORCE_REGISTRY_H

#include <memory>
#include <vector>

#include "sim/spring_network.h"
#include "sim/step_terms.h"

namespace wobble {

struct SimulationParams;

// What a force's factory sees when the Simulation (re)builds its forces: at construction and
// whenever a force's settings change (set_wind).
struct ForceSetup {
  const SimulationParams& params;
  const SpringNetwork& rest;  // rest shape, springs, render triangles, masses
  double rest_diagonal;       // of the rest shape's bounding box (m)
};

// Builds a force for the current params, or returns nullptr when it is off.
using ForceFactory = std::unique_ptr<ForceTerm> (*)(const ForceSetup& setup);

struct ForceEntry {
  const char* name;
  ForceFactory make;
};

// Wobble's own forces, one line each in registered_forces.cpp.
const std::vector<ForceEntry>& built_in_forces();

// Registers a force defined outside src/sim (a plugin, a test fixture) after the built-in ones,
// as one line at namespace scope of its own file:
//   const ForceRegistration push{"push", make_push};
// Registration order among such files is the order of static initialization.
struct ForceRegistration {
  ForceRegistration(const char* name, ForceFactory make);
};

// Every force that is on, in order: the built-in ones, then the registered ones. Each step's
// f_ext starts as gravity (sim/forces/gravity.h), and each force adds to it in this order.
std::vector<std::unique_ptr<ForceTerm>> make_forces(const ForceSetup& setup);

}  // namespace wobble

#endif

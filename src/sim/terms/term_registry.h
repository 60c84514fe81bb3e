#ifndef WOBBLE_SIM_TERMS_TERM_REGISTRY_H
#define WOBBLE_SIM_TERMS_TERM_REGISTRY_H

#include <memory>
#include <vector>

#include "sim/spring_network.h"
#include "sim/terms/step_term.h"

namespace wobble {

struct SimulationParams;

// What a term's factory sees when the Simulation (re)builds its made terms: at construction and
// whenever a setting of theirs changes (set_wind).
struct TermSetup {
  const SimulationParams& params;
  const SpringNetwork& rest;  // rest shape, springs, render triangles, masses
  double rest_diagonal;       // of the rest shape's bounding box (m)
};

// Builds a term for the current params, or returns nullptr when it is off.
using TermFactory = std::unique_ptr<StepTerm> (*)(const TermSetup& setup);

struct TermEntry {
  const char* name;
  TermFactory make;
};

// Wobble's own made terms (the forces: wind), one line each in sim/registered_terms.cpp. The pins
// and contact are the Simulation's own members, since its API edits them.
const std::vector<TermEntry>& built_in_terms();

// Registers a term defined outside src/sim (a plugin, a test fixture) after the built-in ones,
// as one line at namespace scope of its own file:
//   const TermRegistration tether{"tether", make_tether};
// Registration order among such files is the order of static initialization.
struct TermRegistration {
  TermRegistration(const char* name, TermFactory make);
};

// Every made term that is on, in order: the built-in ones, then the registered ones. They come
// after the pins and before contact in the step's list (terms/step_terms.h).
std::vector<std::unique_ptr<StepTerm>> make_terms(const TermSetup& setup);

}  // namespace wobble

#endif

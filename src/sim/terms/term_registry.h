#ifndef WOBBLE_SIM_TERMS_TERM_REGISTRY_H
#define WOBBLE_SIM_TERMS_TERM_REGISTRY_H

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "sim/spring_network.h"
#include "sim/terms/step_term.h"

namespace wobble {

struct SimulationParams;

// What a term's factory sees when the Simulation makes its terms: at construction and whenever
// the settings change.
struct TermSetup {
  const SimulationParams& params;
  const SpringNetwork& rest;            // rest shape, springs, render triangles, masses
  const Eigen::VectorXd& rest_lengths;  // #E r (m)
  double rest_diagonal;                 // of the rest shape's bounding box (m)
};

// Builds a term for the current params, or returns nullptr when it is off.
using TermFactory = std::unique_ptr<StepTerm> (*)(const TermSetup& setup);
// Whether the term made for `before` (or none, where it was off) still serves `after`, so that
// it is kept, with all it has learnt (contact's sets, the colliders where they were dragged), when
// other settings change.
using TermStillServes = bool (*)(const SimulationParams& before, const SimulationParams& after);

struct TermEntry {
  const char* name;
  TermFactory make;
  // nullptr: made anew whenever the settings change.
  TermStillServes still_serves = nullptr;
  // A built-in term that comes after the registered ones: contact, whose projection is the
  // step's last guard.
  bool after_registered = false;
};

// Wobble's own terms (the forces, the volume term, contact), one line each in
// sim/registered_terms.cpp.
const std::vector<TermEntry>& built_in_terms();

// Registers a term defined outside src/sim (a plugin, a test fixture), as one line at namespace
// scope of its own file:
//   const TermRegistration tether{"tether", make_tether};
// Registration order among such files is the order of static initialization.
struct TermRegistration {
  TermRegistration(const char* name, TermFactory make);
};

// The step's terms come in this order, which is the order of every hook over them
// (terms/step_terms.h): the pins (the Simulation's own, as its API edits them), the built-in
// terms (registered_terms.cpp: the wind, the volume term), the terms registered from outside,
// then the built-in ones after_registered (collider contact, then self-contact).
//
// The terms after the pins, one slot per entry in that order (nullptr where off). A slot of
// `terms` made for `before` is kept where its entry says it still serves setup.params; the
// others are made anew. `before` null: all made anew.
void make_terms(const TermSetup& setup, const SimulationParams* before,
                std::vector<std::unique_ptr<StepTerm>>& terms);

}  // namespace wobble

#endif

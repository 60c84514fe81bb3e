// Wobble's own terms, one line each: the factory that reads the settings a term needs (this file
// sits above the terms and the settings value alike, so the terms' own files never read
// SimulationParams), and whether a term made before a change of settings still serves. Adding
// one: its own files (a StepTerm), one line here. Their order: terms/term_registry.h.
#include <memory>
#include <string>

#include "sim/contact/collider_contact_term.h"
#include "sim/contact/self_contact_term.h"
#include "sim/forces/wind.h"
#include "sim/settings/simulation_params.h"
#include "sim/terms/term_registry.h"
#include "sim/volume/volume_term.h"

namespace wobble {

namespace {

std::unique_ptr<StepTerm> make_wind(const TermSetup& setup) {
  return make_wind_force(setup.params.wind, setup.rest_diagonal);
}

// Contact with the colliders, or nullptr without any: the colliders, μ and the contact offset as
// the simulation starts (a running one keeps its colliders, which are dragged, not set).
std::unique_ptr<StepTerm> make_collider_contact(const TermSetup& setup) {
  const ContactParams& contact = setup.params.contact;
  if (contact.colliders.empty()) return nullptr;
  std::vector<Collider> placed = contact.colliders;
  for (std::size_t c = 0; c < placed.size(); ++c)
    validate_collider(placed[c], "collider " + std::to_string(c));  // unit normals
  return std::make_unique<ColliderContactTerm>(ColliderContact(
      std::move(placed), contact.friction,
      resolved_contact_offset(contact.offset, setup.rest_lengths, setup.rest_diagonal)));
}

bool always(const SimulationParams& /*before*/, const SimulationParams& /*after*/) {
  return true;
}

// Self-contact, or nullptr while self-collision is off. Its grids and rest neighbourhoods are
// made only once it is turned on.
std::unique_ptr<StepTerm> make_self_contact(const TermSetup& setup) {
  if (!setup.params.self_collision.on) return nullptr;
  auto term = std::make_unique<SelfContactTerm>(setup.rest);
  term->set(setup.params.self_collision);
  return term;
}

bool same_self_collision(const SimulationParams& before, const SimulationParams& after) {
  return before.self_collision.on == after.self_collision.on &&
         before.self_collision.thickness == after.self_collision.thickness;
}

}  // namespace

const std::vector<TermEntry>& built_in_terms() {
  static const std::vector<TermEntry> terms = {
      {"wind", make_wind},
      {"volume", make_volume_term},
      {"collider contact", make_collider_contact, always, /*after_registered=*/true},
      {"self-contact", make_self_contact, same_self_collision, /*after_registered=*/true},
  };
  return terms;
}

}  // namespace wobble

#include "sim/settings/simulation_params.h"

#include <cmath>
#include <string>

#include "sim/input_error.h"
#include "sim/settings/setting_registry.h"
#include "sim/solver/solver_registry.h"
#include "sim/value_limits.h"

namespace wobble {

void validate_simulation_params(const SimulationParams& params) {
  if (!limits::stiffness.contains(params.k)) {
    throw InputError("k: expected " + expected_in(limits::stiffness) + ", got " +
                     limit_text(params.k));
  }
  if (!limits::time_step.contains(params.dt)) {
    throw InputError("dt: expected " + expected_in(limits::time_step) + ", got " +
                     limit_text(params.dt));
  }
  if (params.iterations < 1 || params.iterations > limits::max_iterations) {
    throw InputError("iterations must be between 1 and " + std::to_string(limits::max_iterations) +
                     ", got " + std::to_string(params.iterations));
  }
  const std::string gravity =
      outside_limits(params.gravity.array(), limits::acceleration, "gravity components");
  if (!gravity.empty()) throw InputError(gravity);
  if (!limits::damping.contains(params.damping)) {
    throw InputError("damping: expected " + expected_in(limits::damping) + ", got " +
                     limit_text(params.damping));
  }
  validate_wind(params.wind);
  validate_self_collision(params.self_collision);
  validate_added_settings(params);
  const ContactParams& contact = params.contact;
  if (!limits::friction.contains(contact.friction)) {
    throw InputError("friction: expected " + expected_in(limits::friction) + ", got " +
                     limit_text(contact.friction));
  }
  if (contact.offset >= 0.0 || std::isnan(contact.offset)) {
    if (!limits::contact_offset.contains(contact.offset)) {
      throw InputError("contact offset: expected " + expected_in(limits::contact_offset) +
                       ", got " + limit_text(contact.offset));
    }
  }
  if (contact.colliders.size() > static_cast<std::size_t>(limits::max_colliders)) {
    throw InputError("at most " + std::to_string(limits::max_colliders) + " colliders, got " +
                     std::to_string(contact.colliders.size()));
  }
  for (std::size_t c = 0; c < contact.colliders.size(); ++c) {
    Collider copy = contact.colliders[c];
    validate_collider(copy, "collider " + std::to_string(c));
  }
  validate_step_solver(params.solver);
}

SimulationParams kept_while_running(const SimulationParams& wanted,
                                    const SimulationParams& in_force) {
  SimulationParams next = wanted;
  next.contact.colliders = in_force.contact.colliders;
  next.contact.offset = in_force.contact.offset;
  next.single_precision_solve_above = in_force.single_precision_solve_above;
  return next;
}

void read_step_settings(const SimulationParams& params, StepContext& step) {
  step.gravity = params.gravity;
  step.friction = params.contact.friction;
}

}  // namespace wobble

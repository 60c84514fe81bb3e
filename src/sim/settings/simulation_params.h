#ifndef WOBBLE_SIM_SETTINGS_SIMULATION_PARAMS_H
#define WOBBLE_SIM_SETTINGS_SIMULATION_PARAMS_H

#include <Eigen/Core>
#include <map>
#include <string>

#include "sim/contact/collider_contact.h"
#include "sim/contact/self_collision.h"
#include "sim/forces/gravity.h"
#include "sim/forces/wind.h"
#include "sim/solver/cholesky_solver.h"
#include "sim/terms/step_term.h"

namespace wobble {

// Where each step's local-global iterations start. They converge to the same positions either
// way; the inertial prediction starts closer (about ten plain iterations closer on a falling
// cloth), as projective dynamics and Wang 2015 start.
enum class FirstIterate {
  current_positions,    // pᵗ, as the course's seed functions do (course scenes keep it)
  inertial_prediction,  // 2pᵗ − pᵗ⁻ᐞᵗ: where inertia alone would carry each vertex
};

struct SimulationParams {
  double k = 1000.0;       // spring stiffness (N/m), > 0
  double dt = 1.0 / 60.0;  // time step (s), > 0
  int iterations = 50;     // local-global iterations per step, 1 to Simulation::max_iterations
  Eigen::Vector3d gravity = Eigen::Vector3d(0.0, -9.81, 0.0);  // m/s² (or N, see gravity_model)
  GravityModel gravity_model = GravityModel::acceleration;
  FirstIterate first_iterate = FirstIterate::inertial_prediction;
  // Chebyshev semi-iterative acceleration of the iterations (Wang 2015). Off by default, and for
  // the course's scenes, whose positions must match the reference.
  bool chebyshev = false;
  // A Cholesky factor with more nonzeros than this is read in single precision by the solve
  // (see CholeskySolver::set_single_precision_above): only the largest scenes, whose factor no
  // longer fits in cache. Course scenes never get near it.
  long single_precision_solve_above = CholeskySolver::default_single_precision_above;
  // Mass-proportional damping c (1/s), folded into the inertia term: with no other force every
  // velocity decays by (1 + cΔt) each step, as exp(−ct) for small Δt. 0: none (course scenes).
  double damping = 0.0;
  // Wind, an explicit force each step (see sim/forces/wind.h). Off unless a scene or the user
  // turns it on.
  WindParams wind;
  // Colliders, friction and the contact offset (see sim/contact/collider_contact.h).
  ContactParams contact;
  // The surface against itself (see sim/contact/self_collision.h). Off by default.
  SelfCollisionParams self_collision;
  // The step solver, by its registered name (see sim/solver/solver_registry.h).
  std::string solver = "local-global";
  // The values given for settings added with a SettingRegistration (sim/settings/
  // setting_registry.h), by name; one left out has its default. Read them with setting_value.
  std::map<std::string, double> added_settings;
};

// Throws InputError unless k, dt, iterations and gravity are within the limits of
// sim/value_limits.h (the same for every way a value comes in), and the solver is registered.
void validate_simulation_params(const SimulationParams& params);

// `wanted` with what a running simulation keeps as it started taken from `in_force`: what its
// terms were made with (the colliders, which are dragged through their term, and the contact
// offset) and single_precision_solve_above.
SimulationParams kept_while_running(const SimulationParams& wanted,
                                    const SimulationParams& in_force);

// What every term may read of the settings at each step: step.gravity and step.friction.
void read_step_settings(const SimulationParams& params, StepContext& step);

}  // namespace wobble

#endif

// Simulation::apply, the one place a change of settings is turned into work: it compares the
// whole settings value with the one in force and does what the difference needs and no more (see
// docs/method.md's table of costs): k, dt and damping re-factorize numerically, the solver and
// Chebyshev prepare the solver, wind and added settings rebuild the made terms, the rest changes
// a value. The setters of one field are each that field changed and applied. Pins re-factorize,
// targets do not.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "forces/gravity.h"
#include "input_error.h"
#include "settings/setting_registry.h"
#include "simulation.h"
#include "solver/solver_registry.h"

namespace wobble {

namespace {

bool same_wind(const WindParams& a, const WindParams& b) {
  return a.on == b.on && a.model == b.model && a.velocity == b.velocity && a.drag == b.drag &&
         a.lift == b.lift && a.gusts == b.gusts && a.air_density == b.air_density;
}

}  // namespace

void Simulation::apply(const SimulationParams& wanted) {
  // Everything that can refuse does so before anything changes.
  validate_simulation_params(wanted);
  SimulationParams next = wanted;
  // What a running simulation keeps as it started: its colliders (translate_collider moves
  // them), the contact offset and the single-precision threshold.
  next.contact.colliders = params_.contact.colliders;
  next.contact.offset = params_.contact.offset;
  next.single_precision_solve_above = params_.single_precision_solve_above;
  if (next.iterations != params_.iterations) check_step_work(next.iterations, /*analyzed=*/true);
  std::unique_ptr<StepSolver> solver;
  if (next.solver != params_.solver) solver = make_step_solver(next.solver, network_.V.rows());

  // What the difference needs, and nothing more (the table of costs in simulation.h).
  bool refactor = next.k != params_.k || next.dt != params_.dt || next.damping != params_.damping;
  bool terms = !same_wind(next.wind, params_.wind);
  if (next.added_settings != params_.added_settings) {
    for (const SettingSpec& spec : added_settings()) {
      if (setting_value(next, spec.name) == setting_value(params_, spec.name)) continue;
      terms = true;
      if (spec.cost == SettingCost::refactorize) refactor = true;
    }
  }
  const bool gravity =
      next.gravity != params_.gravity || next.gravity_model != params_.gravity_model;
  const bool friction = next.contact.friction != params_.contact.friction;
  const bool self = next.self_collision.on != params_.self_collision.on ||
                    next.self_collision.thickness != params_.self_collision.thickness;
  const bool prepare = solver || next.chebyshev != params_.chebyshev;
  // v = (pᵗ − pᵗ⁻ᐞᵗ)/Δt must not change with Δt, so pᵗ⁻ᐞᵗ' = pᵗ − v Δt'.
  if (next.dt != params_.dt) previous_ = current_ - (current_ - previous_) * (next.dt / params_.dt);

  params_ = std::move(next);
  if (solver) solver_ = std::move(solver);
  if (gravity) {
    gravity_fext_ = wobble::gravity_forces(network_.m, params_.gravity, params_.gravity_model);
    fext_ = gravity_fext_;
  }
  if (terms) {
    rebuild_terms();
    if (made_terms_.empty()) fext_ = gravity_fext_;
  }
  if (friction) colliders_.colliders().set_friction(params_.contact.friction);
  if (self) self_collision_.set(params_.self_collision);
  if (refactor) refactorize();
  // Chebyshev's ρ and L-BFGS's history start from the state as it now is.
  if (prepare) prepare_solver();
}

void Simulation::set_k(double k) {
  SimulationParams changed = params_;
  changed.k = k;
  apply(changed);
}

void Simulation::set_dt(double dt) {
  SimulationParams changed = params_;
  changed.dt = dt;
  apply(changed);
}

void Simulation::set_iterations(int iterations) {
  SimulationParams changed = params_;
  changed.iterations = iterations;
  apply(changed);
}

namespace {

int most_iterations(double springs, double factor_nonzeros) {
  const double most = std::floor(limits::max_step_work / std::max(springs + factor_nonzeros, 1.0));
  return static_cast<int>(std::clamp(most, 1.0, static_cast<double>(limits::max_iterations)));
}

}  // namespace

int Simulation::max_iterations_for_mesh() const {
  return most_iterations(static_cast<double>(network_.E.rows()),
                         static_cast<double>(system_.cholesky().factor_nonzeros()));
}

void Simulation::check_step_work(int iterations, bool analyzed) const {
  const double springs = static_cast<double>(network_.E.rows());
  // Before the analysis, the factor is known to hold at least its diagonal: a step that is
  // too much work with that alone is refused before the analysis takes its memory.
  const double factor = analyzed ? static_cast<double>(system_.cholesky().factor_nonzeros())
                                 : static_cast<double>(network_.V.rows());
  const int most = most_iterations(springs, factor);
  if (iterations <= most) return;
  std::ostringstream message;
  message.precision(2);
  message << "iterations and the mesh: " << iterations << " iterations of " << network_.E.rows()
          << " springs and a Cholesky factor of " << (analyzed ? "" : "at least ")
          << static_cast<long>(factor) << " nonzeros are " << (analyzed ? "" : "at least ")
          << iterations * (springs + factor) << " units of work a step, expected at most "
          << limits::max_step_work << ": ";
  if (analyzed) message << "at most " << most << " iterations for this mesh, ";
  message << (analyzed ? "or a coarser mesh" : "fewer iterations or a coarser mesh");
  throw InputError(message.str());
}

void Simulation::set_chebyshev(bool on) {
  SimulationParams changed = params_;
  changed.chebyshev = on;
  apply(changed);
}

void Simulation::set_solver(const std::string& name) {
  SimulationParams changed = params_;
  changed.solver = name;
  apply(changed);
}

void Simulation::set_gravity(const Eigen::Vector3d& gravity, GravityModel model) {
  SimulationParams changed = params_;
  changed.gravity = gravity;
  changed.gravity_model = model;
  apply(changed);
}

void Simulation::pin(int i) {
  pins_.check_vertex(i, "pin");
  if (pins_.pin(i, current_.row(i))) refactorize();
}

void Simulation::unpin(int i) {
  if (pins_.unpin(i)) refactorize();
}

void Simulation::set_pin_target(int i, const Eigen::Vector3d& target) {
  pins_.set_target(i, target);
}

void Simulation::set_damping(double damping) {
  SimulationParams changed = params_;
  changed.damping = damping;
  apply(changed);
}

void Simulation::set_wind(const WindParams& wind) {
  SimulationParams changed = params_;
  changed.wind = wind;
  apply(changed);
}

void Simulation::set_friction(double friction) {
  SimulationParams changed = params_;
  changed.contact.friction = friction;
  apply(changed);
}

void Simulation::translate_collider(int index, const Eigen::Vector3d& offset) {
  if (!offset.allFinite()) throw std::invalid_argument("translate_collider: offset is not finite");
  colliders_.colliders().translate(index, offset);
}

void Simulation::set_self_collision(const SelfCollisionParams& self_collision) {
  SimulationParams changed = params_;
  changed.self_collision = self_collision;
  apply(changed);
}

double Simulation::self_collision_thickness_kept() const {
  return self_collision_.thickness_kept(params_.self_collision.thickness);
}

int Simulation::self_contact_count() const {
  return self_collision_.contact_count();
}

const std::vector<char>& Simulation::self_contact_vertices() const {
  return self_collision_.contact_vertices();
}

bool Simulation::is_pinned(int i) const {
  pins_.check_vertex(i, "is_pinned");
  return pins_.flags()[i] != 0;
}

std::vector<int> Simulation::pinned_vertices() const {
  return pins_.list();
}

Eigen::Vector3d Simulation::pin_target(int i) const {
  pins_.check_vertex(i, "pin_target");
  return pins_.targets().row(i).transpose();
}

void Simulation::set_iteration_observer(std::function<void(int, const Eigen::MatrixXd&)> observer) {
  callback_.set(std::move(observer));
  update_observers();
}

void Simulation::set_convergence_recording(bool on) {
  record_convergence_ = on;
  // Sized once, so that recording allocates nothing per iteration.
  if (on) recorder_.reserve(max_iterations);
  update_observers();
}

}  // namespace wobble

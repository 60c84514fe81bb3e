// The Simulation's setters: each changes what it must and no more (see docs/method.md's table of
// costs): k and dt re-factorize numerically, pins re-factorize, targets and iterations do not.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "forces/gravity.h"
#include "input_error.h"
#include "simulation.h"
#include "solver/solver_registry.h"

namespace wobble {

void Simulation::set_k(double k) {
  SimulationParams changed = params_;
  changed.k = k;
  validate_simulation_params(changed);
  params_.k = k;
  refactorize();
}

void Simulation::set_dt(double dt) {
  SimulationParams changed = params_;
  changed.dt = dt;
  validate_simulation_params(changed);
  // v = (pᵗ − pᵗ⁻ᐞᵗ)/Δt must not change, so pᵗ⁻ᐞᵗ' = pᵗ − v Δt'.
  previous_ = current_ - (current_ - previous_) * (dt / params_.dt);
  params_.dt = dt;
  refactorize();
}

void Simulation::set_iterations(int iterations) {
  SimulationParams changed = params_;
  changed.iterations = iterations;
  validate_simulation_params(changed);
  check_step_work(iterations, /*analyzed=*/true);
  params_.iterations = iterations;
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
  params_.chebyshev = on;
  prepare_solver();
}

void Simulation::set_solver(const std::string& name) {
  std::unique_ptr<StepSolver> solver = make_step_solver(name, network_.V.rows());
  params_.solver = name;
  solver_ = std::move(solver);
  prepare_solver();
}

void Simulation::set_gravity(const Eigen::Vector3d& gravity, GravityModel model) {
  SimulationParams changed = params_;
  changed.gravity = gravity;
  validate_simulation_params(changed);
  params_.gravity = gravity;
  params_.gravity_model = model;
  gravity_fext_ = wobble::gravity_forces(network_.m, gravity, model);
  fext_ = gravity_fext_;
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
  validate_simulation_params(changed);
  if (damping == params_.damping) return;
  params_.damping = damping;
  refactorize();
}

void Simulation::set_wind(const WindParams& wind) {
  validate_wind(wind);
  params_.wind = wind;
  rebuild_terms();
  if (made_terms_.empty()) fext_ = gravity_fext_;
}

void Simulation::set_friction(double friction) {
  SimulationParams changed = params_;
  changed.contact.friction = friction;
  validate_simulation_params(changed);
  params_.contact.friction = friction;
  colliders_.colliders().set_friction(friction);
}

void Simulation::translate_collider(int index, const Eigen::Vector3d& offset) {
  if (!offset.allFinite()) throw std::invalid_argument("translate_collider: offset is not finite");
  colliders_.colliders().translate(index, offset);
}

void Simulation::set_self_collision(const SelfCollisionParams& self_collision) {
  SimulationParams changed = params_;
  changed.self_collision = self_collision;
  validate_simulation_params(changed);
  params_.self_collision = self_collision;
  self_collision_.set(self_collision);
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

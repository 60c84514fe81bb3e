// Simulation::apply, the one place a change of settings is turned into work: it compares the
// whole settings value with the one in force, setting by setting over their declarations
// (sim/settings/setting_registry.h), and does what the costs of those that changed need and no
// more (see docs/method.md's table of costs). Pins re-factorize, targets do not.
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

void Simulation::apply(const SimulationParams& wanted) {
  // Everything that can refuse does so before anything changes.
  validate_simulation_params(wanted);
  SimulationParams next = kept_while_running(wanted, params_);
  // What the difference costs: the costs of every setting whose value changed.
  SettingCost cost = SettingCost::value;
  for (const SettingSpec& spec : all_settings()) {
    if (spec.get(next) != spec.get(params_)) cost = cost | spec.cost;
  }
  const auto needs = [cost](SettingCost what) { return costs(cost, what); };
  if (needs(SettingCost::step_work)) check_step_work(next.iterations, /*analyzed=*/true);
  std::unique_ptr<StepSolver> solver;
  if (needs(SettingCost::solver)) solver = make_step_solver(next.solver, network_.V.rows());
  // v = (pᵗ − pᵗ⁻ᐞᵗ)/Δt must not change with Δt, so pᵗ⁻ᐞᵗ' = pᵗ − v Δt'.
  if (needs(SettingCost::time_step)) {
    previous_ = current_ - (current_ - previous_) * (next.dt / params_.dt);
  }

  const SimulationParams before = std::move(params_);
  params_ = std::move(next);
  if (solver) solver_ = std::move(solver);
  if (needs(SettingCost::gravity)) {
    gravity_fext_ = wobble::gravity_forces(network_.m, params_.gravity, params_.gravity_model);
    fext_ = gravity_fext_;
  }
  if (needs(SettingCost::terms)) {
    rebuild_terms(&before);
    if (!any_term_made_) fext_ = gravity_fext_;
  }
  if (needs(SettingCost::factorization)) refactorize();
  // Chebyshev's ρ and L-BFGS's history start from the state as it now is.
  if (needs(SettingCost::solver_state)) prepare_solver();
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

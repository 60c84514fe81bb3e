#include "simulation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "forces/gravity.h"
#include "input_error.h"
#include "instruments/stopwatch.h"
#include "solver/damped_inertia.h"
#include "solver/solver_registry.h"
#include "terms/term_registry.h"

namespace wobble {

namespace {

// Throws InputError unless `positions` is a finite n by 3 matrix; `what` names it.
void check_vertex_matrix(const Eigen::MatrixXd& positions, Eigen::Index n, const char* what) {
  if (positions.rows() != n || positions.cols() != 3 || !positions.allFinite()) {
    throw InputError(std::string(what) + " must be a finite " + std::to_string(n) + " by 3 matrix");
  }
}

}  // namespace

Simulation::Simulation(SpringNetwork network, const std::vector<int>& pins,
                       const SimulationParams& params, Eigen::MatrixXd initial_velocity)
    : network_(std::move(network)),
      params_(params),
      initial_velocity_(std::move(initial_velocity)) {
  const Stopwatch stopwatch;
  validate_spring_network(network_);
  validate_simulation_params(params_);
  const Eigen::Index n = network_.V.rows();
  if (initial_velocity_.size() != 0) check_vertex_matrix(initial_velocity_, n, "initial velocity");
  for (int i : pins) {
    if (i < 0 || i >= n) {
      throw InputError("pinned vertex " + std::to_string(i) + " is out of range 0 to " +
                       std::to_string(n - 1));
    }
  }
  std::vector<int> initial_pins = pins;
  std::sort(initial_pins.begin(), initial_pins.end());
  initial_pins.erase(std::unique(initial_pins.begin(), initial_pins.end()), initial_pins.end());

  const Eigen::MatrixXi& E = network_.E;
  r_.resize(E.rows());
  for (Eigen::Index e = 0; e < E.rows(); ++e) {
    r_(e) = (network_.V.row(E(e, 0)) - network_.V.row(E(e, 1))).norm();
  }
  system_ = SystemMatrix(E, n);
  local_step_ = std::make_unique<LocalStep>(E, r_, network_.V);
  const double diagonal =
      n == 0 ? 0.0 : (network_.V.colwise().maxCoeff() - network_.V.colwise().minCoeff()).norm();
  jump_limit_ = 100.0 * (diagonal > 0.0 ? diagonal : 1.0);  // a single vertex: 1 m
  rest_diagonal_ = diagonal > 0.0 ? diagonal : 1.0;
  solver_ = make_step_solver(params_.solver, n);
  previous_.resize(n, 3);
  current_.resize(n, 3);
  next_.resize(n, 3);
  y_.resize(n, 3);
  pins_ = Pins(initial_pins, network_.V);
  rebuild_terms(nullptr);
  gravity_fext_ = wobble::gravity_forces(network_.m, params_.gravity, params_.gravity_model);
  fext_ = gravity_fext_;

  system_.cholesky().set_single_precision_above(params_.single_precision_solve_above);
  check_step_work(params_.iterations, /*analyzed=*/false);
  system_.analyze();
  check_step_work(params_.iterations, /*analyzed=*/true);  // before the factor is computed
  refactorize();
  reset();
  prepare_solver();
  precompute_ms_ = stopwatch.milliseconds();
}

void Simulation::reset() {
  current_ = network_.V;
  previous_ = network_.V;
  if (initial_velocity_.size() != 0) previous_ -= params_.dt * initial_velocity_;
  steps_taken_ = 0;
  time_ = 0.0;
  last_status_ = StepStatus::ok;
  const bool pins_changed = pins_.reset(network_.V);
  if (terms_.reset() || pins_changed) refactorize();
}

void Simulation::set_state(const Eigen::MatrixXd& current, const Eigen::MatrixXd& previous) {
  check_vertex_matrix(current, network_.V.rows(), "current positions");
  check_vertex_matrix(previous, network_.V.rows(), "previous positions");
  current_ = current;
  previous_ = previous;
}

StepStatus Simulation::step() {
  const Stopwatch step_stopwatch;
  const Stopwatch forces_stopwatch;
  apply_forces();
  const double forces_ms = forces_stopwatch.milliseconds();
  compute_y();
  start_iterate();
  const StepContext context = step_context();
  if (terms_.begin_step(context, next_)) refactorize();
  // The scale the step's convergence is read against: the gradient inertia alone would have with
  // every vertex a mean spring rest length off (along one axis), ‖m‖₂ r̄ / Δt².
  if (record_convergence_) {
    const double rest = r_.size() > 0 ? r_.mean() : 0.0;
    recorder_.set_force_scale(network_.m.norm() * rest / (params_.dt * params_.dt));
  }
  solver_->solve(step_problem(), observers_, next_, timing_);
  terms_.project(context, next_);
  terms_.report(timing_.figures);

  last_status_ = check_step();
  if (last_status_ == StepStatus::ok) {
    previous_.swap(current_);
    current_.swap(next_);
    ++steps_taken_;
    time_ += params_.dt;
    terms_.end_step();
  }
  timing_.forces_ms = forces_ms;
  timing_.total_ms = step_stopwatch.milliseconds();
  return last_status_;
}

StepStatus Simulation::check_step() const {
  // One pass over the new positions; a NaN fails every comparison, so test finiteness first.
  const double limit2 = jump_limit_ * jump_limit_;
  bool jumped = false;
  for (Eigen::Index i = 0; i < next_.rows(); ++i) {
    double distance2 = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double p = next_(i, c);
      if (!std::isfinite(p)) return StepStatus::not_finite;
      const double away = p - (2.0 * current_(i, c) - previous_(i, c));
      distance2 += away * away;
    }
    if (!(distance2 <= limit2)) jumped = true;
  }
  return jumped ? StepStatus::jumped : StepStatus::ok;
}

std::string Simulation::describe(StepStatus status) {
  switch (status) {
    case StepStatus::ok:
      return "the step succeeded";
    case StepStatus::not_finite:
      return "the step produced non-finite positions and was rolled back; try a smaller dt or "
             "more iterations";
    case StepStatus::jumped:
      return "the step moved a vertex more than 100 times the shape's size and was rolled back; "
             "try a smaller dt or more iterations";
  }
  return "unknown step status";
}

void Simulation::compute_y() {
  // y = M((2 + cΔt)pᵗ − pᵗ⁻ᐞᵗ)/Δt² + f_ext + w CᵀC p_target: fixed for the whole step.
  inertial_right_hand_side(network_.m, current_, previous_, params_.dt, params_.damping, y_);
  y_ += fext_;
  terms_.add_fixed_rhs(y_);
}

void Simulation::start_iterate() {
  if (params_.first_iterate == FirstIterate::inertial_prediction) {
    inertial_prediction(current_, previous_, params_.dt, params_.damping, next_);
  } else {
    next_ = current_;
  }
}

void Simulation::prepare_solver() {
  compute_y();
  start_iterate();
  solver_->prepare(step_problem(), next_);
}

StepProblem Simulation::step_problem() {
  return StepProblem{
      network_,
      r_,
      SolveSettings{params_.k, params_.dt, params_.damping, params_.iterations, params_.chebyshev},
      current_,
      previous_,
      fext_,
      y_,
      system_,
      *local_step_,
      terms_,
      step_context(),
      terms_.touching()};
}

StepContext Simulation::step_context() const {
  StepContext context{network_, current_, previous_, pins_.flags(), params_.dt, time_};
  read_step_settings(params_, context);
  context.extrapolated = solver_ && solver_->extrapolates();
  if (base_diagonal_.size() == network_.V.rows()) {
    context.base_diagonal = &base_diagonal_;
    context.inertia = &inertia_;
  }
  return context;
}

void Simulation::rebuild_terms(const SimulationParams* before) {
  make_terms(TermSetup{params_, network_, r_, rest_diagonal_}, before, made_terms_);
  std::vector<StepTerm*> list{&pins_};
  any_term_made_ = false;
  for (const auto& term : made_terms_) {
    if (!term) continue;
    list.push_back(term.get());
    any_term_made_ = true;
  }
  terms_.set(std::move(list));
  // The made terms' fixed part of Q (the volume term's); the caller refactorizes. A pattern that
  // had to grow is analyzed again (never in the constructor, which analyzes after this).
  if (system_.set_terms_matrix(terms_.matrix(network_.V.rows())) && system_.symbolic_analyses() > 0)
    system_.analyze();
}

void Simulation::apply_forces() {
  if (!any_term_made_) return;  // fext_ already holds gravity alone
  fext_ = gravity_fext_;
  terms_.add_forces(step_context(), fext_);
}

void Simulation::refactorize() {
  base_diagonal_ = system_.base_diagonal(params_.k, params_.dt, params_.damping, network_.m);
  inertia_ = inertia_scale(params_.dt, params_.damping) * network_.m;
  system_.refactorize(params_.k, params_.dt, params_.damping, network_.m,
                      terms_.diagonal(step_context()));
}

void Simulation::update_observers() {
  std::vector<StepObserver*> observers;
  if (record_convergence_) observers.push_back(&recorder_);
  if (!callback_.empty()) observers.push_back(&callback_);
  observers_.set(std::move(observers));
}

double Simulation::step_energy(const Eigen::MatrixXd& p, Eigen::MatrixXd* gradient) const {
  return step_objective(StepObjectiveTerms{network_.E, r_, network_.m, params_.k, params_.dt,
                                           params_.damping, current_, previous_, fext_},
                        p, gradient) +
         terms_.add_energy(step_context(), p, gradient);
}

Eigen::MatrixXd Simulation::velocities() const {
  return (current_ - previous_) / params_.dt;
}

FrameEnergy frame_energy(const Simulation& simulation) {
  return frame_energy(simulation.rest(), simulation.rest_lengths(), simulation.params().k,
                      simulation.params().dt, simulation.positions(),
                      simulation.previous_positions(), simulation.gravity_forces());
}

}  // namespace wobble

#include "simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "input_error.h"
#include "value_limits.h"

namespace wobble {

namespace {

using Clock = std::chrono::steady_clock;

double milliseconds_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Throws InputError unless `positions` is a finite n by 3 matrix; `what` names it.
void check_vertex_matrix(const Eigen::MatrixXd& positions, Eigen::Index n, const char* what) {
  if (positions.rows() != n || positions.cols() != 3 || !positions.allFinite()) {
    throw InputError(std::string(what) + " must be a finite " + std::to_string(n) + " by 3 matrix");
  }
}

// AᵀA for the springs E (no spring from a vertex to itself): +1 at (i,i) and (j,j) and -1 at
// (i,j) and (j,i) for every spring, springs repeated summing up. Every diagonal entry is stored,
// zero for a vertex without springs, so that masses and pins only ever change values: one
// symbolic analysis serves every later factorization. Built column by column straight into
// compressed storage (setFromTriplets on the 1.6 million triplets of the 256×256 cloth took
// 40–50 ms).
Eigen::SparseMatrix<double> spring_laplacian(const Eigen::MatrixXi& E, Eigen::Index n) {
  // Each column's entries, unsorted: the diagonal first, then one -1 per spring.
  std::vector<int> start(n + 1, 0);
  for (Eigen::Index e = 0; e < E.rows(); ++e) {
    ++start[E(e, 0) + 1];
    ++start[E(e, 1) + 1];
  }
  for (Eigen::Index i = 0; i < n; ++i)
    start[i + 1] += start[i] + 1;
  std::vector<int> rows(start[n]), next(start.begin(), start.end() - 1);
  std::vector<double> diagonal(n, 0.0);
  for (Eigen::Index i = 0; i < n; ++i)
    rows[next[i]++] = static_cast<int>(i);
  for (Eigen::Index e = 0; e < E.rows(); ++e) {
    const int i = E(e, 0), j = E(e, 1);
    rows[next[i]++] = j;
    rows[next[j]++] = i;
    diagonal[i] += 1.0;
    diagonal[j] += 1.0;
  }
  // Sorted, repeats merged, into the matrix's own arrays.
  Eigen::SparseMatrix<double> L(n, n);
  L.resizeNonZeros(start[n]);
  int* outer = L.outerIndexPtr();
  int* inner = L.innerIndexPtr();
  double* value = L.valuePtr();
  int stored = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    outer[i] = stored;
    std::sort(rows.begin() + start[i], rows.begin() + start[i + 1]);
    for (int s = start[i]; s < start[i + 1]; ++s) {
      const int row = rows[s];
      const double v = row == i ? diagonal[i] : -1.0;
      if (stored > outer[i] && inner[stored - 1] == row) {
        value[stored - 1] += v;
      } else {
        inner[stored] = row;
        value[stored++] = v;
      }
    }
  }
  outer[n] = stored;
  L.resizeNonZeros(stored);
  return L;
}

// The contact offset a scene asked for, or else a tenth of the median spring rest length: enough
// to keep the flat triangles between contact vertices out of a curved collider, small enough
// not to be seen as a gap (a 40×40 cloth of 1 m: 3.6 mm).
double resolved_contact_offset(double asked, const Eigen::VectorXd& rest_lengths,
                               double rest_diagonal) {
  if (asked >= 0.0) return asked;
  if (rest_lengths.size() == 0) return 0.005 * rest_diagonal;
  std::vector<double> lengths(rest_lengths.data(), rest_lengths.data() + rest_lengths.size());
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  return 0.1 * lengths[lengths.size() / 2];
}

}  // namespace

void validate_simulation_params(const SimulationParams& params) {
  if (!limits::stiffness.contains(params.k)) {
    throw InputError("k: expected " + expected_in(limits::stiffness) + ", got " +
                     limit_text(params.k));
  }
  if (!limits::time_step.contains(params.dt)) {
    throw InputError("dt: expected " + expected_in(limits::time_step) + ", got " +
                     limit_text(params.dt));
  }
  if (params.iterations < 1 || params.iterations > Simulation::max_iterations) {
    throw InputError("iterations must be between 1 and " +
                     std::to_string(Simulation::max_iterations) + ", got " +
                     std::to_string(params.iterations));
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
}

Simulation::Simulation(SpringNetwork network, const std::vector<int>& pins,
                       const SimulationParams& params, Eigen::MatrixXd initial_velocity)
    : network_(std::move(network)),
      params_(params),
      initial_velocity_(std::move(initial_velocity)) {
  const auto start = Clock::now();
  validate_spring_network(network_);
  validate_simulation_params(params_);
  for (std::size_t c = 0; c < params_.contact.colliders.size(); ++c)
    validate_collider(params_.contact.colliders[c], "collider " + std::to_string(c));
  const Eigen::Index n = network_.V.rows();
  if (initial_velocity_.size() != 0) check_vertex_matrix(initial_velocity_, n, "initial velocity");
  for (int i : pins) {
    if (i < 0 || i >= n) {
      throw InputError("pinned vertex " + std::to_string(i) + " is out of range 0 to " +
                       std::to_string(n - 1));
    }
  }
  initial_pins_ = pins;
  std::sort(initial_pins_.begin(), initial_pins_.end());
  initial_pins_.erase(std::unique(initial_pins_.begin(), initial_pins_.end()), initial_pins_.end());

  const Eigen::MatrixXi& E = network_.E;
  r_.resize(E.rows());
  for (Eigen::Index e = 0; e < E.rows(); ++e) {
    r_(e) = (network_.V.row(E(e, 0)) - network_.V.row(E(e, 1))).norm();
  }

  laplacian_ = spring_laplacian(E, n);
  Q_ = laplacian_;
  diagonal_slot_.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const int* rows = Q_.innerIndexPtr();
    for (Eigen::Index s = Q_.outerIndexPtr()[i]; s < Q_.outerIndexPtr()[i + 1]; ++s) {
      if (rows[s] == i) diagonal_slot_[i] = s;
    }
  }

  local_step_ = std::make_unique<LocalStep>(E, r_, network_.V);
  const double diagonal =
      n == 0 ? 0.0 : (network_.V.colwise().maxCoeff() - network_.V.colwise().minCoeff()).norm();
  jump_limit_ = 100.0 * (diagonal > 0.0 ? diagonal : 1.0);  // a single vertex: 1 m
  rest_diagonal_ = diagonal > 0.0 ? diagonal : 1.0;
  contact_ = ColliderContact(params_.contact.colliders, params_.contact.friction,
                             resolved_contact_offset(params_.contact.offset, r_, rest_diagonal_));
  // Self-collision's grids and rest neighbourhoods are made only once it is turned on.
  if (params_.self_collision.on) {
    self_collision_ = std::make_unique<SelfCollision>(network_, params_.self_collision);
  }
  rebuild_forces();
  chebyshev_ = ChebyshevAcceleration(n);
  solved_.resize(n, 3);
  previous_.resize(n, 3);
  current_.resize(n, 3);
  next_.resize(n, 3);
  y_.resize(n, 3);
  rhs_.resize(n, 3);
  targets_ = network_.V;
  pinned_.assign(n, 0);
  for (int i : initial_pins_)
    pinned_[i] = 1;
  pin_count_ = static_cast<int>(initial_pins_.size());
  update_external_forces();

  solver_.set_single_precision_above(params_.single_precision_solve_above);
  check_step_work(params_.iterations, /*analyzed=*/false);
  solver_.analyze(Q_);
  ++symbolic_analyses_;
  check_step_work(params_.iterations, /*analyzed=*/true);  // before the factor is computed
  refactorize();
  reset();
  if (params_.chebyshev) calibrate_chebyshev();
  precompute_ms_ = milliseconds_since(start);
}

void Simulation::reset() {
  current_ = network_.V;
  previous_ = network_.V;
  if (initial_velocity_.size() != 0) previous_ -= params_.dt * initial_velocity_;
  targets_ = network_.V;
  steps_taken_ = 0;
  time_ = 0.0;
  last_status_ = StepStatus::ok;
  contact_ = ColliderContact(params_.contact.colliders, contact_.friction(), contact_.offset());
  if (self_collision_) self_collision_->clear();

  std::vector<char> initial(pinned_.size(), 0);
  for (int i : initial_pins_)
    initial[i] = 1;
  if (initial != pinned_) {
    pinned_ = std::move(initial);
    pin_count_ = static_cast<int>(initial_pins_.size());
    refactorize();
  }
}

void Simulation::set_state(const Eigen::MatrixXd& current, const Eigen::MatrixXd& previous) {
  check_vertex_matrix(current, network_.V.rows(), "current positions");
  check_vertex_matrix(previous, network_.V.rows(), "previous positions");
  current_ = current;
  previous_ = previous;
}

StepStatus Simulation::step() {
  const auto step_start = Clock::now();
  const double k = params_.k;

  const auto forces_start = Clock::now();
  apply_forces();
  const double forces_ms = milliseconds_since(forces_start);
  compute_y();

  start_iterate();
  double instruments_ms = 0.0;
  if (record_convergence_) {
    trace_.energy.clear();
    trace_.gradient_norm.clear();
    trace_.chebyshev = params_.chebyshev;
  }
  double springs = 0.0;  // Σ(‖pᵢ − pⱼ‖ − rᵢⱼ)² at the iterate, from the local step
  if (params_.chebyshev) chebyshev_.start(next_);
  restart_iteration_ = 0;
  // Contact makes a step's problem change sharply from one iteration to the next; with ρ near 1
  // the extrapolation then runs away (a cloth falling on a sphere left it at 48 m/s). While the
  // last step touched a collider, an iteration whose update grew restarts the recurrence.
  const bool restart_on_growth =
      contact_.contact_count() > 0 || (params_.self_collision.on && self_contact_count() > 0);
  double local_ms = 0.0, global_ms = 0.0;
  for (int iteration = 0; iteration < params_.iterations; ++iteration) {
    const auto local_start = Clock::now();
    local_step_->apply(next_, k, y_, rhs_, record_convergence_ ? &springs : nullptr);
    local_ms += milliseconds_since(local_start);
    if (record_convergence_) {
      const auto record_start = Clock::now();
      // The first iterate is a prediction; an accelerated one is not the solve's output.
      record_iterate(springs, iteration > 0 && !params_.chebyshev);
      instruments_ms += milliseconds_since(record_start);
    }
    const auto global_start = Clock::now();

    // With acceleration every iteration but the last is accelerated; the last, plain, removes
    // what the acceleration leaves of the fast components (see chebyshev.h).
    if (params_.chebyshev && iteration + 1 < params_.iterations) {
      solver_.solve(rhs_, solved_);
      accelerate(iteration, restart_on_growth);
    } else {
      solver_.solve(rhs_, next_);
    }
    global_ms += milliseconds_since(global_start);
    if (observer_) observer_(iteration, next_);
  }
  if (record_convergence_) {
    // The last iterate, which no local step has seen yet.
    const auto record_start = Clock::now();
    local_step_->apply(next_, k, y_, rhs_, &springs);
    record_iterate(springs, /*plain_solve=*/true);  // the last iteration is never accelerated
    instruments_ms += milliseconds_since(record_start);
  }

  const auto contact_start = Clock::now();
  contact_.project(step_context(), next_);
  timing_.contact_ms = milliseconds_since(contact_start);
  timing_.self_detection_ms = timing_.self_response_ms = 0.0;
  if (params_.self_collision.on) {
    collide_with_itself();
    timing_.self_detection_ms = self_collision_->detection_ms();
    timing_.self_response_ms = self_collision_->response_ms();
  }

  last_status_ = check_step();
  if (last_status_ == StepStatus::ok) {
    previous_.swap(current_);
    current_.swap(next_);
    ++steps_taken_;
    time_ += params_.dt;
    contact_.end_step();
  }
  timing_.local_ms = local_ms;
  timing_.global_ms = global_ms;
  timing_.forces_ms = forces_ms;
  timing_.instruments_ms = instruments_ms;
  timing_.total_ms = milliseconds_since(step_start);
  return last_status_;
}

void Simulation::collide_with_itself() {
  // Pinned vertices do not give way to a layer pushing on them, and vertices a collider holds
  // give way as if they weighed 20 times as much: a pile's top layer is pushed up off the bottom
  // one, not the bottom one into the ground (the colliders' second pass puts back what did go
  // in), yet two layers that both lie on the ground still separate.
  constexpr double held_by_collider = 1.0 / 20.0;
  const std::vector<char>& on_collider = contact_.contact_vertices();
  const bool any_collider = !on_collider.empty();
  inverse_mass_.resize(network_.m.size());
  for (Eigen::Index i = 0; i < inverse_mass_.size(); ++i) {
    const double scale = pinned_[i] ? 0.0 : any_collider && on_collider[i] ? held_by_collider : 1.0;
    inverse_mass_(i) = scale / network_.m(i);
  }
  self_collision_->project(current_, inverse_mass_, contact_.friction(), next_);
  if (self_collision_->pair_count() > 0 && !contact_.empty()) {
    // A collider can push a vertex the layers squeeze against it back through a layer: the
    // layers get the last word, and what they push into a collider stays within its offset.
    const auto contact_start = Clock::now();
    contact_.project_again(step_context(), next_);
    timing_.contact_ms += milliseconds_since(contact_start);
    self_collision_->project_again(inverse_mass_, next_);
  }
  self_collision_->finish(current_, inverse_mass_, next_);
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
  const double inverse_dt2 = 1.0 / (params_.dt * params_.dt);
  const double damped = 2.0 + params_.damping * params_.dt;
  y_.noalias() = network_.m.asDiagonal() * (damped * current_ - previous_);
  y_ *= inverse_dt2;
  y_ += fext_;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(pinned_.size()); ++i) {
    if (pinned_[i]) y_.row(i) += pin_weight * targets_.row(i);
  }
}

void Simulation::start_iterate() {
  if (params_.first_iterate == FirstIterate::inertial_prediction) {
    // ((2 + cΔt)pᵗ − pᵗ⁻ᐞᵗ)/(1 + cΔt): where inertia and damping alone carry each vertex.
    if (params_.damping == 0.0) {
      next_ = 2.0 * current_ - previous_;
    } else {
      const double cdt = params_.damping * params_.dt;
      next_ = ((2.0 + cdt) * current_ - previous_) / (1.0 + cdt);
    }
  } else {
    next_ = current_;
  }
}

void Simulation::accelerate(int iteration, bool restart_on_growth) {
  if (restart_on_growth) {
    const double update = (solved_ - next_).squaredNorm();
    const bool grew = iteration > 0 && update > last_update_;
    last_update_ = update;
    if (grew) {
      chebyshev_.start(solved_);  // a plain iteration, and the recurrence starts again from it
      next_.swap(solved_);
      restart_iteration_ = iteration;
      return;
    }
  }
  chebyshev_.accelerate(iteration - restart_iteration_, solved_, next_);
}

void Simulation::calibrate_chebyshev() {
  // The paper's calibration: plain iterations of one step, from the current state, watching the
  // updates shrink. Nothing of the state changes. The ratio of updates settles slowly on a soft
  // cloth: from iterations 20–40 it reads ρ ≈ 0.97 where the error shrinks by 0.985–0.99 per
  // iteration, and a ρ that low gives away most of the gain; from 50–100 it reads 0.98–0.99.
  compute_y();
  std::vector<double> update_norms;
  start_iterate();
  for (int iteration = 0; iteration < chebyshev_calibration_iterations; ++iteration) {
    local_step_->apply(next_, params_.k, y_, rhs_);
    solver_.solve(rhs_, solved_);
    update_norms.push_back((solved_ - next_).norm());
    next_.swap(solved_);
  }
  chebyshev_.set_spectral_radius(ChebyshevAcceleration::estimate_spectral_radius(update_norms));
  chebyshev_calibrated_ = true;
}

void Simulation::set_iteration_observer(std::function<void(int, const Eigen::MatrixXd&)> observer) {
  observer_ = std::move(observer);
}

StepObjectiveTerms Simulation::objective_terms() const {
  return StepObjectiveTerms{network_.E,      r_,        network_.m, params_.k, params_.dt,
                            params_.damping, current_,  previous_,  fext_,     pinned_,
                            targets_,        pin_weight};
}

double Simulation::step_energy(const Eigen::MatrixXd& p, Eigen::MatrixXd* gradient) const {
  return step_objective(objective_terms(), p, gradient);
}

void Simulation::set_convergence_recording(bool on) {
  record_convergence_ = on;
  if (!on) return;
  // Sized once, so that recording allocates nothing per iteration.
  trace_.energy.reserve(max_iterations + 1);
  trace_.gradient_norm.reserve(max_iterations + 1);
  gradient_.resize(network_.V.rows(), 3);
  previous_rhs_.resize(network_.V.rows(), 3);
}

void Simulation::record_iterate(double springs, bool plain_solve) {
  // rhs_ holds k Aᵀd(p) + y for the iterate p = next_, so the objective's gradient is Q p − rhs:
  // k AᵀA p − k Aᵀd(p) is the springs' part, the rest the inertia, f_ext and the pins. When p
  // came straight out of a double-precision solve of Q p = previous_rhs_, Q p is that right-hand
  // side to rounding, and the product is not needed (it would cost as much as a local step).
  double squared = 0.0;
  if (plain_solve && !solver_.solves_in_single_precision()) {
    // One pass: the difference, its norm, and the right-hand side kept for the next iterate.
    double* previous = previous_rhs_.data();
    const double* rhs = rhs_.data();
    for (Eigen::Index s = 0; s < rhs_.size(); ++s) {
      const double difference = previous[s] - rhs[s];
      squared += difference * difference;
      previous[s] = rhs[s];
    }
  } else {
    gradient_.noalias() = Q_ * next_;
    gradient_ -= rhs_;
    squared = gradient_.squaredNorm();
    previous_rhs_ = rhs_;
  }
  trace_.gradient_norm.push_back(std::sqrt(squared));
  trace_.energy.push_back(step_objective_vertex_terms(objective_terms(), next_) +
                          0.5 * params_.k * springs);
}

Eigen::MatrixXd Simulation::velocities() const {
  return (current_ - previous_) / params_.dt;
}

void Simulation::check_vertex(int i, const char* what) const {
  if (i < 0 || i >= static_cast<int>(pinned_.size())) {
    throw std::out_of_range(std::string(what) + ": vertex " + std::to_string(i) +
                            " is out of range 0 to " + std::to_string(pinned_.size() - 1));
  }
}

void Simulation::update_external_forces() {
  const Eigen::RowVector3d g = params_.gravity.transpose();
  if (params_.gravity_model == GravityModel::acceleration) {
    gravity_fext_ = network_.m * g;
  } else {
    gravity_fext_ = g.replicate(network_.V.rows(), 1);
  }
  fext_ = gravity_fext_;
}

void Simulation::rebuild_forces() {
  forces_.clear();
  if (!params_.wind.on) return;
  if (params_.wind.model == WindModel::course) {
    forces_.push_back(std::make_unique<CourseWind>(rest_diagonal_));
  } else {
    forces_.push_back(std::make_unique<AerodynamicWind>(params_.wind));
  }
}

StepContext Simulation::step_context() const {
  return StepContext{network_, current_, previous_, pinned_, params_.dt, time_};
}

void Simulation::apply_forces() {
  if (forces_.empty()) return;  // fext_ already holds gravity alone
  fext_ = gravity_fext_;
  const StepContext context = step_context();
  for (const auto& force : forces_)
    force->apply_forces(context, fext_);
}

void Simulation::refactorize() {
  // Q = k AᵀA + (1 + cΔt)M/Δt² + w CᵀC, written into the fixed pattern.
  const double* laplacian = laplacian_.valuePtr();
  double* q = Q_.valuePtr();
  for (Eigen::Index s = 0; s < Q_.nonZeros(); ++s)
    q[s] = params_.k * laplacian[s];
  // Damping scales the inertia term by (1 + cΔt).
  const double inertia = (1.0 + params_.damping * params_.dt) / (params_.dt * params_.dt);
  for (std::size_t i = 0; i < diagonal_slot_.size(); ++i) {
    q[diagonal_slot_[i]] += network_.m(i) * inertia + (pinned_[i] ? pin_weight : 0.0);
  }
  ++numeric_factorizations_;
  if (!solver_.factorize(Q_)) throw std::runtime_error("the Cholesky factorization of Q failed");
}

}  // namespace wobble

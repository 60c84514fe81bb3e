#include "sim/contact/collider_contact_term.h"

#include <stdexcept>

#include "sim/instruments/stopwatch.h"

namespace wobble {

void ColliderContactTerm::add_diagonal(const StepContext& step, Eigen::VectorXd& diagonal) {
  // κ follows Q's own diagonal (k, Δt, damping) for the set it holds.
  if (!contact_.empty() && step.base_diagonal && step.inertia)
    solve_.set_base_diagonal(*step.base_diagonal, *step.inertia);
  const Eigen::VectorXd& weights = solve_.weights();
  if (weights.size() == diagonal.size()) diagonal += weights;
}

TermStep ColliderContactTerm::begin_step(const StepContext& step, const Eigen::MatrixXd& first) {
  const Stopwatch stopwatch;
  contact_.set_friction(step.friction);
  // Chebyshev's extrapolation needs Q to describe the contact it meets: the set on Q's diagonal
  // follows the contact set every step while the solver extrapolates.
  solve_.set_lagging(!step.extrapolated);
  // Gravity's reach over a step (‖g‖Δt², m), part of the contact set's margin.
  const double gravity_reach = step.gravity.norm() * step.dt * step.dt;
  // A scene without colliders never gets here with anything to do: its Q and its steps stay
  // those of the plain method, to the bit.
  if (contact_.empty()) {
    held_changed_ = solve_.clear();
  } else {
    held_changed_ = solve_.choose(contact_, step, first, gravity_reach);
    if (!solve_.members().empty()) solve_.lag_friction(contact_, step);
  }
  choose_ms_ = stopwatch.milliseconds();
  TermStep begun;
  begun.in_solve = !solve_.empty();
  begun.diagonal_changed = held_changed_;
  begun.touching = contact_.contact_count() > 0;
  return begun;
}

void ColliderContactTerm::add_targets(const StepContext& step, const Eigen::MatrixXd& p,
                                      Eigen::MatrixXd& rhs, double* energy) {
  solve_.add_targets(contact_, step, p, rhs, energy);
}

double ColliderContactTerm::add_energy(const StepContext& step, const Eigen::MatrixXd& p,
                                       Eigen::MatrixXd* gradient) const {
  if (solve_.members().empty()) return 0.0;
  return solve_.energy(contact_, step, p, gradient);
}

void ColliderContactTerm::project(const StepContext& step, Eigen::MatrixXd& next) {
  if (!solve_.members().empty()) solve_.record_forces(contact_, next);
  contact_.project(step, next);
  if (!solve_.members().empty()) contact_.mark_pressed(solve_.touching());
}

void ColliderContactTerm::end_step() {
  contact_.end_step();
}

bool ColliderContactTerm::reset() {
  contact_ = ColliderContact(placed_, contact_.friction(), contact_.offset());
  return solve_.clear();
}

void ColliderContactTerm::translate(int index, const Eigen::Vector3d& offset) {
  if (!offset.allFinite()) throw std::invalid_argument("translate_collider: offset is not finite");
  contact_.translate(index, offset);
}

const std::vector<Collider>& colliders_in(const StepTerms& terms) {
  static const std::vector<Collider> none;
  const ColliderContactTerm* term = terms.find<ColliderContactTerm>();
  return term ? term->colliders().colliders() : none;
}

const std::vector<char>& collider_contact_vertices(const StepTerms& terms) {
  static const std::vector<char> none;
  const ColliderContactTerm* term = terms.find<ColliderContactTerm>();
  return term ? term->colliders().contact_vertices() : none;
}

void ColliderContactTerm::report(std::vector<TermFigure>& figures) const {
  if (contact_.empty()) return;
  const char* term = name();
  figures.push_back(TermFigure{term, "time", "ms", choose_ms_ + contact_.milliseconds()});
  figures.push_back(
      TermFigure{term, "contacts", "", static_cast<double>(contact_.contact_count())});
  figures.push_back(
      TermFigure{term, "in the solve", "", static_cast<double>(solve_.members().size())});
  figures.push_back(TermFigure{term, "Q refactorized", "", held_changed_ ? 1.0 : 0.0});
}

}  // namespace wobble

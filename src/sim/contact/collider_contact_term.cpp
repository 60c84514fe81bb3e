#include "sim/contact/collider_contact_term.h"

#include "sim/instruments/stopwatch.h"

namespace wobble {

void ColliderContactTerm::set_base_diagonal(const Eigen::VectorXd& base,
                                            const Eigen::VectorXd& inertia) {
  if (!contact_.empty()) solve_.set_base_diagonal(base, inertia);
}

void ColliderContactTerm::add_diagonal(Eigen::VectorXd& diagonal) const {
  const Eigen::VectorXd& weights = solve_.weights();
  if (weights.size() == diagonal.size()) diagonal += weights;
}

bool ColliderContactTerm::begin_step(const StepContext& step, const Eigen::MatrixXd& first) {
  const Stopwatch stopwatch;
  // A scene without colliders never gets here with anything to do: its Q and its steps stay
  // those of the plain method, to the bit.
  if (contact_.empty()) {
    held_changed_ = solve_.clear();
  } else {
    held_changed_ = solve_.choose(contact_, step, first, gravity_reach_);
    if (!solve_.members().empty()) solve_.lag_friction(contact_, step);
  }
  choose_ms_ = stopwatch.milliseconds();
  return held_changed_;
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

bool ColliderContactTerm::restart(const std::vector<Collider>& placed) {
  contact_ = ColliderContact(placed, contact_.friction(), contact_.offset());
  return solve_.clear();
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

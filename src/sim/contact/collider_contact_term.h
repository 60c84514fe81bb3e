#ifndef WOBBLE_SIM_CONTACT_COLLIDER_CONTACT_TERM_H
#define WOBBLE_SIM_CONTACT_COLLIDER_CONTACT_TERM_H

#include <Eigen/Core>
#include <vector>

#include "sim/contact/collider_contact.h"
#include "sim/contact/solve_contact.h"
#include "sim/terms/step_term.h"

namespace wobble {

// Contact with the colliders as one term of the step: inside the solve (SolveContact: the
// vertices near a collider drawn out of it, κ on Q's diagonal for a lagged set), then the
// projection after the solve (ColliderContact) as the last guard. Off (nothing at all) in a
// scene without colliders, whose steps stay those of the plain method to the bit.
class ColliderContactTerm : public StepTerm {
 public:
  ColliderContactTerm() = default;
  // `contact` holds the colliders, μ and the resolved offset.
  explicit ColliderContactTerm(ColliderContact contact) : contact_(std::move(contact)) {}

  const char* name() const override { return "collider contact"; }
  void set_base_diagonal(const Eigen::VectorXd& base, const Eigen::VectorXd& inertia) override;
  void add_diagonal(Eigen::VectorXd& diagonal) const override;
  bool begin_step(const StepContext& step, const Eigen::MatrixXd& first) override;
  bool in_solve() const override { return !solve_.empty(); }
  void add_targets(const StepContext& step, const Eigen::MatrixXd& p, Eigen::MatrixXd& rhs,
                   double* energy) override;
  double add_energy(const StepContext& step, const Eigen::MatrixXd& p,
                    Eigen::MatrixXd* gradient) const override;
  void project(const StepContext& step, Eigen::MatrixXd& next) override;
  void end_step() override;
  bool in_contact() const override { return contact_.contact_count() > 0; }
  void report(std::vector<TermFigure>& figures) const override;

  // Back to the colliders where the scene placed them (`placed`), μ and the offset kept.
  // Returns whether κ left Q's diagonal.
  bool restart(const std::vector<Collider>& placed);
  // Gravity's reach over a step (‖g‖Δt², m), part of the contact set's margin.
  void set_gravity_reach(double reach) { gravity_reach_ = reach; }
  // Whether the set on Q's diagonal lags behind the contact set (SolveContact::set_lagging).
  void set_lagging(bool on) { solve_.set_lagging(on); }

  ColliderContact& colliders() { return contact_; }
  const ColliderContact& colliders() const { return contact_; }
  const SolveContact& solve() const { return solve_; }

 private:
  ColliderContact contact_;
  SolveContact solve_;
  double gravity_reach_ = 0.0;
  double choose_ms_ = 0.0;
  bool held_changed_ = false;
};

}  // namespace wobble

#endif

#ifndef WOBBLE_SIM_CONTACT_COLLIDER_CONTACT_TERM_H
#define WOBBLE_SIM_CONTACT_COLLIDER_CONTACT_TERM_H

#include <Eigen/Core>
#include <vector>

#include "sim/contact/collider_contact.h"
#include "sim/contact/solve_contact.h"
#include "sim/terms/step_term.h"
#include "sim/terms/step_terms.h"

namespace wobble {

// Contact with the colliders as one term of the step: inside the solve (SolveContact: the
// vertices near a collider drawn out of it, κ on Q's diagonal for a lagged set), then the
// projection after the solve (ColliderContact) as the last guard. Off (nothing at all) in a
// scene without colliders, whose steps stay those of the plain method to the bit.
class ColliderContactTerm : public StepTerm {
 public:
  ColliderContactTerm() = default;
  // `contact` holds the colliders where the scene placed them (reset() puts them back there), μ
  // and the resolved offset. Each step then takes μ, gravity's reach and whether its set lags
  // from the step (StepContext).
  explicit ColliderContactTerm(ColliderContact contact)
      : placed_(contact.colliders()), contact_(std::move(contact)) {}

  const char* name() const override { return "collider contact"; }
  void add_diagonal(const StepContext& step, Eigen::VectorXd& diagonal) override;
  TermStep begin_step(const StepContext& step, const Eigen::MatrixXd& first) override;
  void add_targets(const StepContext& step, const Eigen::MatrixXd& p, Eigen::MatrixXd& rhs,
                   double* energy) override;
  double add_energy(const StepContext& step, const Eigen::MatrixXd& p,
                    Eigen::MatrixXd* gradient) const override;
  void project(const StepContext& step, Eigen::MatrixXd& next) override;
  void report(std::vector<TermFigure>& figures) const override;
  void end_step() override;
  // Back to the colliders where the scene placed them, μ and the offset kept. Returns whether κ
  // left Q's diagonal.
  bool reset() override;

  // Moves collider `index` rigidly by `offset` (m), no re-factorization. Throws
  // std::invalid_argument for a non-finite offset, std::out_of_range for a bad index.
  void translate(int index, const Eigen::Vector3d& offset);

  ColliderContact& colliders() { return contact_; }
  const ColliderContact& colliders() const { return contact_; }
  const SolveContact& solve() const { return solve_; }

 private:
  std::vector<Collider> placed_;
  ColliderContact contact_;
  SolveContact solve_;
  double choose_ms_ = 0.0;
  bool held_changed_ = false;
};

// The colliders among a step's terms where they are now (none without collider contact), and
// the vertices the last step moved out of one (#V flags; empty without).
const std::vector<Collider>& colliders_in(const StepTerms& terms);
const std::vector<char>& collider_contact_vertices(const StepTerms& terms);

}  // namespace wobble

#endif

#ifndef WOBBLE_SIM_CONTACT_SELF_COLLISION_CONSTRAINT_H
#define WOBBLE_SIM_CONTACT_SELF_COLLISION_CONSTRAINT_H

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "sim/contact/collider_contact.h"
#include "sim/contact/self_collision.h"
#include "sim/spring_network.h"
#include "sim/terms/step_term.h"

namespace wobble {

// Self-collision (sim/contact/self_collision.h) as the step's constraint after the colliders:
// the surface pushed apart from itself with vertex i weighted by 1/mᵢ (0 when pinned, 1/(20mᵢ)
// when a collider holds it), then the colliders once more for what that pushed into them. Its
// grids and rest neighbourhoods are made when it is first turned on; off, it does nothing.
class SelfCollisionConstraint : public StepTerm {
 public:
  // Both must outlive it: `rest` the network (F and masses), `colliders` the step's colliders.
  SelfCollisionConstraint(const SpringNetwork& rest, ColliderContact& colliders);

  // On, off or a new thickness; the params must already be valid.
  void set(const SelfCollisionParams& params);
  // Forget the last step's pairs (Simulation::reset).
  void clear();

  const char* name() const override { return "self-contact"; }
  void project(const StepContext& step, Eigen::MatrixXd& next) override;
  bool in_contact() const override { return contact_count() > 0; }
  void report(std::vector<TermFigure>& figures) const override;
  // Vertices the last step moved, while on.
  int contact_count() const;

  const std::vector<char>& contact_vertices() const;  // #V flags, or empty
  double thickness_kept(double asked) const;          // see Simulation

 private:
  const SpringNetwork* rest_;
  ColliderContact* colliders_;
  bool on_ = false;
  std::unique_ptr<SelfCollision> self_collision_;  // made when first turned on
  Eigen::VectorXd inverse_mass_;                   // #V: the weights above (1/kg)
};

}  // namespace wobble

#endif

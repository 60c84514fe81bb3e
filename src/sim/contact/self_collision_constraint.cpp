#include "sim/contact/self_collision_constraint.h"

namespace wobble {

SelfCollisionConstraint::SelfCollisionConstraint(const SpringNetwork& rest,
                                                 ColliderContact& colliders)
    : rest_(&rest), colliders_(&colliders) {}

void SelfCollisionConstraint::set(const SelfCollisionParams& params) {
  on_ = params.on;
  if (!self_collision_ && params.on) {
    self_collision_ = std::make_unique<SelfCollision>(*rest_, params);
  } else if (self_collision_) {
    self_collision_->set_thickness(params.thickness);
    if (!params.on) self_collision_->clear();
  }
}

void SelfCollisionConstraint::clear() {
  if (self_collision_) self_collision_->clear();
}

void SelfCollisionConstraint::project(const StepContext& step, Eigen::MatrixXd& next) {
  if (!on_) return;
  // Pinned vertices do not give way to a layer pushing on them, and vertices a collider holds
  // give way as if they weighed 20 times as much: a pile's top layer is pushed up off the bottom
  // one, not the bottom one into the ground (the colliders' second pass puts back what did go
  // in), yet two layers that both lie on the ground still separate.
  constexpr double held_by_collider = 1.0 / 20.0;
  const std::vector<char>& on_collider = colliders_->contact_vertices();
  const bool any_collider = !on_collider.empty();
  const Eigen::VectorXd& m = step.rest.m;
  inverse_mass_.resize(m.size());
  for (Eigen::Index i = 0; i < inverse_mass_.size(); ++i) {
    const double scale = step.pinned[i]                   ? 0.0
                         : any_collider && on_collider[i] ? held_by_collider
                                                          : 1.0;
    inverse_mass_(i) = scale / m(i);
  }
  self_collision_->project(step.current, inverse_mass_, colliders_->friction(), next);
  if (self_collision_->pair_count() > 0 && !colliders_->empty()) {
    // A collider can push a vertex the layers squeeze against it back through a layer: the
    // layers get the last word, and what they push into a collider stays within its offset.
    colliders_->project_again(step, next);
    self_collision_->project_again(inverse_mass_, next);
  }
  self_collision_->finish(step.current, inverse_mass_, next);
}

int SelfCollisionConstraint::contact_count() const {
  return on_ && self_collision_ ? self_collision_->contact_count() : 0;
}

void SelfCollisionConstraint::report(std::vector<TermFigure>& figures) const {
  if (!on_) return;
  const char* term = name();
  figures.push_back(TermFigure{term, "detection", "ms", self_collision_->detection_ms()});
  figures.push_back(TermFigure{term, "response", "ms", self_collision_->response_ms()});
  figures.push_back(TermFigure{term, "contacts", "", static_cast<double>(contact_count())});
}

const std::vector<char>& SelfCollisionConstraint::contact_vertices() const {
  static const std::vector<char> none;
  return self_collision_ ? self_collision_->contact_vertices() : none;
}

double SelfCollisionConstraint::thickness_kept(double asked) const {
  return self_collision_ ? self_collision_->thickness() : asked;
}

}  // namespace wobble

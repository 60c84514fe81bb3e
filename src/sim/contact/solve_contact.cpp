#include "sim/contact/solve_contact.h"

#include <algorithm>
#include <limits>

namespace wobble {

namespace {

// The smallest signed distance from p to a collider (m), and which collider.
double nearest_collider(const std::vector<Collider>& colliders, const Eigen::Vector3d& p,
                        int* which = nullptr) {
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < colliders.size(); ++c) {
    const double distance = collider_surface(colliders[c], p).distance;
    if (distance < nearest) {
      nearest = distance;
      if (which) *which = static_cast<int>(c);
    }
  }
  return nearest;
}

}  // namespace

bool SolveContact::choose(const ColliderContact& contact, const StepContext& step,
                          const Eigen::MatrixXd& first, double gravity_reach) {
  const Eigen::Index n = first.rows();
  if (contact.empty() || base_.size() != n) return clear();
  if (static_cast<Eigen::Index>(member_flags_.size()) != n) member_flags_.assign(n, 0);
  if (static_cast<Eigen::Index>(held_flags_.size()) != n) held_flags_.assign(n, 0);
  if (normal_force_.size() != n) normal_force_.setZero(n);
  if (static_cast<Eigen::Index>(touching_.size()) != n) touching_.assign(n, 0);
  members_.clear();
  int outside = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    bool member = false;
    if (!step.pinned[i]) {
      const Eigen::Vector3d p = first.row(i).transpose();
      const double motion = (p - step.current.row(i).transpose()).norm();
      const double margin = contact.offset() + 2.0 * motion + gravity_reach;
      const double distance = nearest_collider(contact.colliders(), p) - contact.offset();
      member = distance < (member_flags_[i] ? 2.0 * margin : margin);
    }
    member_flags_[i] = member;
    if (member) {
      members_.push_back(static_cast<int>(i));
      if (!held_flags_[i]) ++outside;
    } else {
      normal_force_(i) = 0.0;
      touching_[i] = 0;
    }
  }
  ++steps_since_chosen_;
  // H is chosen again when a member is outside it or it holds a vertex that left S, no sooner
  // than lag_steps after the last time, and at once for a first contact.
  int held_only = 0;
  for (int i : held_)
    held_only += !member_flags_[i];
  const bool due = held_.empty() ? !members_.empty()
                                 : steps_since_chosen_ >= (lagging_ ? lag_steps : 1) &&
                                       (outside > 0 || held_only > 0);
  bool changed = false;
  if (due) {
    held_.clear();
    for (Eigen::Index i = 0; i < n; ++i) {
      held_flags_[i] = member_flags_[i];
      if (held_flags_[i]) held_.push_back(static_cast<int>(i));
    }
    weights_.setZero(n);
    for (int i : held_)
      weights_(i) = weight_scale * base_(i);
    if (held_.empty()) weights_.resize(0);
    steps_since_chosen_ = 0;
    changed = true;
  }
  held_only_.clear();
  for (int i : held_) {
    if (!member_flags_[i]) held_only_.push_back(i);
  }
  return changed;
}

void SolveContact::set_base_diagonal(const Eigen::VectorXd& base, const Eigen::VectorXd& inertia) {
  base_ = base;
  inertia_ = inertia;
  for (int i : held_)
    weights_(i) = weight_scale * base_(i);
}

double SolveContact::member_weight(int i) const {
  return held_flags_[i] ? weights_(i) : rhs_weight_scale * inertia_(i);
}

void SolveContact::record_forces(const ColliderContact& contact, const Eigen::MatrixXd& p) {
  if (normal_force_.size() != p.rows()) normal_force_.setZero(p.rows());
  if (static_cast<Eigen::Index>(touching_.size()) != p.rows()) touching_.assign(p.rows(), 0);
  // Resting on a collider, a vertex the springs hold up ends a hair outside the offset: within
  // 1% of it counts as touching.
  const double reach = 0.01 * contact.offset();
  for (int i : members_) {
    const double depth =
        contact.offset() - nearest_collider(contact.colliders(), p.row(i).transpose());
    normal_force_(i) = member_weight(i) * std::max(depth, 0.0);
    touching_[i] = depth > -reach;
  }
}

bool SolveContact::clear() {
  const bool held = !held_.empty();
  members_.clear();
  member_flags_.clear();
  held_.clear();
  held_flags_.clear();
  held_only_.clear();
  steps_since_chosen_ = 0;
  weights_.resize(0);
  normal_force_.resize(0);
  touching_.clear();
  return held;
}

void SolveContact::add_targets(const ColliderContact& contact, const StepContext& step,
                               const Eigen::MatrixXd& p, Eigen::MatrixXd& rhs,
                               double* energy) const {
  double sum = 0.0;
  for (int i : members_) {
    const Eigen::Vector3d at = p.row(i).transpose();
    const Eigen::Vector3d target = contact.outside_point(step, i, at);
    const double kappa = member_weight(i);
    if (held_flags_[i]) {
      rhs.row(i) += kappa * target.transpose();
    } else {
      rhs.row(i) += kappa * (target - at).transpose();
    }
    sum += 0.5 * kappa * (at - target).squaredNorm();
  }
  // H less S: the target is the vertex itself, so κ on the diagonal only slows it.
  for (int i : held_only_)
    rhs.row(i) += weights_(i) * p.row(i);
  if (energy) *energy += sum;
}

void SolveContact::lag_friction(const ColliderContact& contact, const StepContext& step) {
  friction_normal_.assign(members_.size(), Eigen::Vector3d::UnitY());
  friction_force_.assign(members_.size(), 0.0);
  friction_collider_.assign(members_.size(), -1);
  for (std::size_t s = 0; s < members_.size(); ++s) {
    const int i = members_[s];
    if (step.pinned[i]) continue;
    const Eigen::Vector3d p = step.current.row(i).transpose();
    int which = -1;
    nearest_collider(contact.colliders(), p, &which);
    if (which < 0) continue;
    const Collider& collider = contact.colliders()[which];
    const ColliderSurface surface = collider_surface(collider, p);
    const double mu = collider.friction >= 0.0 ? collider.friction : contact.friction();
    const double lambda = normal_force_.size() > i ? normal_force_(i) : 0.0;
    if (!(mu > 0.0) || !(lambda > 0.0)) continue;
    friction_normal_[s] = surface.normal;
    friction_force_[s] = mu * lambda;
    friction_collider_[s] = which;
  }
}

double SolveContact::energy(const ColliderContact& contact, const StepContext& step,
                            const Eigen::MatrixXd& p, Eigen::MatrixXd* gradient) const {
  const double offset = contact.offset();
  // Huber's width: slides below it are held as by a stiff spring (static friction).
  const double epsilon = 0.01 * offset;
  double energy = 0.0;
  for (std::size_t s = 0; s < members_.size(); ++s) {
    const int i = members_[s];
    const double kappa = member_weight(i);
    const Eigen::Vector3d at = p.row(i).transpose();
    for (const Collider& collider : contact.colliders()) {
      const ColliderSurface surface = collider_surface(collider, at);
      const double depth = offset - surface.distance;
      if (!(depth > 0.0)) continue;
      energy += 0.5 * kappa * depth * depth;
      if (gradient) gradient->row(i) -= kappa * depth * surface.normal.transpose();
    }
    if (s < friction_collider_.size() && friction_collider_[s] >= 0 && friction_force_[s] > 0.0) {
      const Eigen::Vector3d& normal = friction_normal_[s];
      const Eigen::Vector3d moved =
          at - step.current.row(i).transpose() - contact.motion(friction_collider_[s]);
      const Eigen::Vector3d slide = moved - moved.dot(normal) * normal;
      const double length = slide.norm();
      const double force = friction_force_[s];
      if (length < epsilon) {
        energy += force * length * length / (2.0 * epsilon);
        if (gradient) gradient->row(i) += (force / epsilon) * slide.transpose();
      } else {
        energy += force * (length - 0.5 * epsilon);
        if (gradient) gradient->row(i) += (force / length) * slide.transpose();
      }
    }
  }
  return energy;
}

}  // namespace wobble

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
  bool changed = false;
  for (Eigen::Index i = 0; i < n; ++i) {
    bool member = false;
    if (!step.pinned[i]) {
      const Eigen::Vector3d p = first.row(i).transpose();
      const double motion = (p - step.current.row(i).transpose()).norm();
      const double margin = contact.offset() + 2.0 * motion + gravity_reach;
      const double distance = nearest_collider(contact.colliders(), p) - contact.offset();
      member = distance < (member_flags_[i] ? 2.0 * margin : margin);
    }
    if (member != static_cast<bool>(member_flags_[i])) {
      member_flags_[i] = member;
      changed = true;
    }
  }
  if (!changed) return false;
  if (normal_force_.size() != n) normal_force_.setZero(n);
  members_.clear();
  weights_.setZero(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!member_flags_[i]) {
      normal_force_(i) = 0.0;
      if (static_cast<Eigen::Index>(touching_.size()) == n) touching_[i] = 0;
      continue;
    }
    members_.push_back(static_cast<int>(i));
    weights_(i) = weight_scale * base_(i);
  }
  if (members_.empty()) weights_.resize(0);
  return true;
}

void SolveContact::set_base_diagonal(Eigen::VectorXd base) {
  base_ = std::move(base);
  for (int i : members_)
    weights_(i) = weight_scale * base_(i);
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
    normal_force_(i) = weights_(i) * std::max(depth, 0.0);
    touching_[i] = depth > -reach;
  }
}

bool SolveContact::clear() {
  const bool held = !members_.empty();
  members_.clear();
  member_flags_.clear();
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
    rhs.row(i) += weights_(i) * target.transpose();
    sum += 0.5 * weights_(i) * (at - target).squaredNorm();
  }
  if (energy) *energy = sum;
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
    const double kappa = weights_(i);
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

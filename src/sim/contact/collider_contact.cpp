#include "sim/contact/collider_contact.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "sim/instruments/stopwatch.h"

namespace wobble {

// Enough to keep the flat triangles between contact vertices out of a curved collider, small
// enough not to be seen as a gap (a 40×40 cloth of 1 m: 3.6 mm).
double resolved_contact_offset(double asked, const Eigen::VectorXd& rest_lengths,
                               double rest_diagonal) {
  if (asked >= 0.0) return asked;
  if (rest_lengths.size() == 0) return 0.005 * rest_diagonal;
  std::vector<double> lengths(rest_lengths.data(), rest_lengths.data() + rest_lengths.size());
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  return 0.1 * lengths[lengths.size() / 2];
}

ColliderContact::ColliderContact(std::vector<Collider> colliders, double friction, double offset)
    : colliders_(std::move(colliders)),
      motion_(colliders_.size(), Eigen::Vector3d::Zero()),
      friction_(friction),
      offset_(offset) {}

void ColliderContact::project(const StepContext& step, Eigen::MatrixXd& next) {
  const Stopwatch stopwatch;
  contact_count_ = 0;
  if (!colliders_.empty()) {
    touched_.assign(next.rows(), 0);
    project_vertices(step, next);
  }
  milliseconds_ = stopwatch.milliseconds();
}

void ColliderContact::project_again(const StepContext& step, Eigen::MatrixXd& next) {
  const Stopwatch stopwatch;
  if (!colliders_.empty()) project_vertices(step, next);
  milliseconds_ += stopwatch.milliseconds();
}

void ColliderContact::project_vertices(const StepContext& step, Eigen::MatrixXd& next) {
  for (Eigen::Index i = 0; i < next.rows(); ++i) {
    bool touched = false;
    next.row(i) = outside_point(step, i, next.row(i).transpose(), &touched).transpose();
    if (touched && !touched_[i]) {
      touched_[i] = 1;
      ++contact_count_;
    }
  }
}

Eigen::Vector3d ColliderContact::outside_point(const StepContext& step, Eigen::Index i,
                                               Eigen::Vector3d p, bool* touched) const {
  // A vertex pushed out of one collider can land in another (a box standing on the ground): a
  // second pass settles such corners.
  const int passes = colliders_.size() > 1 ? 2 : 1;
  for (int pass = 0; pass < passes; ++pass) {
    for (std::size_t c = 0; c < colliders_.size(); ++c) {
      const Collider& collider = colliders_[c];
      const ColliderSurface surface = collider_surface(collider, p);
      const double depth = offset_ - surface.distance;
      if (!(depth > 0.0)) continue;
      if (touched) *touched = true;
      p += depth * surface.normal;
      // A pinned vertex follows its target, not the surface's friction.
      if (step.pinned[i]) continue;
      const double mu = collider.friction >= 0.0 ? collider.friction : friction_;
      if (!(mu > 0.0)) continue;
      const Eigen::Vector3d moved = p - step.current.row(i).transpose() - motion_[c];
      const Eigen::Vector3d tangential = moved - moved.dot(surface.normal) * surface.normal;
      const double slide = tangential.norm();
      const double budget = mu * depth;
      p -= slide <= budget ? tangential : tangential * (budget / slide);
      // Undoing a slide along a curved surface can dip back in by its sagitta.
      const ColliderSurface again = collider_surface(collider, p);
      if (again.distance < offset_) p += (offset_ - again.distance) * again.normal;
    }
  }
  return p;
}

void ColliderContact::mark_pressed(const std::vector<char>& touching) {
  if (touched_.size() != touching.size()) return;
  for (std::size_t i = 0; i < touching.size(); ++i) {
    if (touching[i] && !touched_[i]) {
      touched_[i] = 1;
      ++contact_count_;
    }
  }
}

void ColliderContact::end_step() {
  for (Eigen::Vector3d& motion : motion_)
    motion.setZero();
}

void ColliderContact::translate(int index, const Eigen::Vector3d& offset) {
  if (index < 0 || index >= static_cast<int>(colliders_.size())) {
    throw std::out_of_range("translate_collider: collider " + std::to_string(index) +
                            " does not exist");
  }
  translate_collider(colliders_[index], offset);
  motion_[index] += offset;
}

}  // namespace wobble

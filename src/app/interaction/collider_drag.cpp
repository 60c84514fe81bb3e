#include "app/interaction/collider_drag.h"
#include "sim/contact/collider_contact_term.h"

namespace wobble {

void ColliderDrag::grab(const Simulation& simulation, int index, const Eigen::Vector3f& grab_point,
                        const Eigen::Vector3f& view_direction) {
  index_ = index;
  plane_point_ = held_ = grab_point;
  plane_normal_ = view_direction.normalized();
  reach_ = static_cast<float>(reach_in_jump_limits * simulation.jump_limit());
}

void ColliderDrag::move(Simulation& simulation, const Ray& cursor) {
  if (!active()) return;
  const std::optional<Eigen::Vector3f> hit = intersect_plane(cursor, plane_point_, plane_normal_);
  if (!hit) return;
  // A ray grazing the plane meets it very far away: keep the collider within reach.
  Eigen::Vector3f away = *hit - plane_point_;
  const float distance = away.norm();
  if (!(distance <= reach_)) away *= reach_ / distance;
  const Eigen::Vector3f target = plane_point_ + away;
  simulation.term<ColliderContactTerm>()->translate(index_, (target - held_).cast<double>());
  held_ = target;
}

}  // namespace wobble

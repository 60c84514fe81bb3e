#include "app/interaction/vertex_drag.h"

namespace wobble {

void VertexDrag::grab(Simulation& simulation, int vertex, const Ray& cursor,
                      const Eigen::Vector3f& view_direction) {
  was_free_ = !simulation.is_pinned(vertex);
  // A free vertex is pinned where it is; a pinned one is held at its target, not where the
  // springs have pulled it to.
  if (was_free_) simulation.pin(vertex);
  vertex_ = vertex;
  plane_point_ = simulation.pin_target(vertex).cast<float>();
  plane_normal_ = view_direction.normalized();
  const std::optional<Eigen::Vector3f> hit = intersect_plane(cursor, plane_point_, plane_normal_);
  offset_ = hit ? Eigen::Vector3f(plane_point_ - *hit) : Eigen::Vector3f::Zero();
  reach_ = static_cast<float>(reach_in_jump_limits * simulation.jump_limit());
}

void VertexDrag::move(Simulation& simulation, const Ray& cursor) {
  if (!active()) return;
  // A cursor ray parallel to the plane (or behind the eye) leaves the target where it was.
  const std::optional<Eigen::Vector3f> hit = intersect_plane(cursor, plane_point_, plane_normal_);
  if (!hit) return;
  // A ray that grazes the plane meets it very far away; keep the target within reach, so that
  // a hard drag to the horizon cannot fling the shape off.
  Eigen::Vector3f away = *hit + offset_ - plane_point_;
  const float distance = away.norm();
  if (!(distance <= reach_)) away *= reach_ / distance;
  simulation.set_pin_target(vertex_, (plane_point_ + away).cast<double>());
}

void VertexDrag::release(Simulation& simulation) {
  if (!active()) return;
  if (was_free_) simulation.unpin(vertex_);
  vertex_ = -1;
}

}  // namespace wobble

#ifndef WOBBLE_APP_INTERACTION_VERTEX_DRAG_H
#define WOBBLE_APP_INTERACTION_VERTEX_DRAG_H

#include <Eigen/Core>

#include "app/interaction/picking.h"
#include "sim/simulation.h"

namespace wobble {

// Holding a vertex with the mouse. The held vertex's pin target follows the cursor in the plane
// through the vertex that faces the camera, so dragging only moves a target: no
// re-factorization. A free vertex is pinned for the length of the drag and let go on release,
// keeping the velocity the drag gave it.
class VertexDrag {
 public:
  // Take hold of `vertex`. `cursor` is the ray under the mouse now; `view_direction` the
  // camera's forward vector (the plane's normal).
  void grab(Simulation& simulation, int vertex, const Ray& cursor,
            const Eigen::Vector3f& view_direction);
  // Move the target under the new cursor ray.
  void move(Simulation& simulation, const Ray& cursor);
  // Let go; a vertex that was free before the grab is free again.
  void release(Simulation& simulation);
  // Forget the drag without touching the simulation (it was replaced or reset).
  void cancel() { vertex_ = -1; }

  bool active() const { return vertex_ >= 0; }
  int vertex() const { return vertex_; }
  bool holds_free_vertex() const { return active() && was_free_; }

  // How far from the grab point a target may go, as a fraction of Simulation::jump_limit():
  // ten times the shape's size, which also keeps every frame's move well inside the limit.
  static constexpr double reach_in_jump_limits = 0.1;

 private:
  int vertex_ = -1;
  bool was_free_ = false;
  Eigen::Vector3f plane_point_ = Eigen::Vector3f::Zero();
  Eigen::Vector3f plane_normal_ = Eigen::Vector3f::UnitZ();
  // From the cursor's point on the plane to the vertex at the grab, so that grabbing a few pixels
  // off the vertex does not make it jump.
  Eigen::Vector3f offset_ = Eigen::Vector3f::Zero();
  float reach_ = 0.0f;
};

}  // namespace wobble

#endif

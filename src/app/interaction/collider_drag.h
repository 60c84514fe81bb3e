#ifndef WOBBLE_APP_INTERACTION_COLLIDER_DRAG_H
#define WOBBLE_APP_INTERACTION_COLLIDER_DRAG_H

#include <Eigen/Core>

#include "app/interaction/picking.h"
#include "sim/simulation.h"

namespace wobble {

// Moving a collider with the mouse (Alt+left-drag), as a pin is dragged: the grabbed surface
// point follows the cursor in the plane through it that faces the camera, and the collider moves
// rigidly with it through its term, ColliderContactTerm::translate (no re-factorization).
class ColliderDrag {
 public:
  // Take hold of collider `index` at `grab_point` (m, on its surface under the cursor);
  // `view_direction` is the camera's forward vector (the plane's normal).
  void grab(const Simulation& simulation, int index, const Eigen::Vector3f& grab_point,
            const Eigen::Vector3f& view_direction);
  // Move the collider so that the grab point lies under the new cursor ray.
  void move(Simulation& simulation, const Ray& cursor);
  void release() { index_ = -1; }
  // Forget the drag (the simulation was replaced or reset).
  void cancel() { index_ = -1; }

  bool active() const { return index_ >= 0; }
  int collider() const { return index_; }

  // How far from where it was grabbed the grab point may go, as a fraction of
  // Simulation::jump_limit(): the same reach as a dragged vertex.
  static constexpr double reach_in_jump_limits = 0.1;

 private:
  int index_ = -1;
  Eigen::Vector3f plane_point_ = Eigen::Vector3f::Zero();  // the grab point at the grab
  Eigen::Vector3f plane_normal_ = Eigen::Vector3f::UnitZ();
  Eigen::Vector3f held_ = Eigen::Vector3f::Zero();  // where the grab point is now
  float reach_ = 0.0f;
};

}  // namespace wobble

#endif

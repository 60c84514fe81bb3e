#ifndef WOBBLE_SIM_CONTACT_COLLIDER_CONTACT_H
#define WOBBLE_SIM_CONTACT_COLLIDER_CONTACT_H

#include <Eigen/Core>
#include <vector>

#include "sim/contact/collider.h"
#include "sim/terms/step_term.h"

namespace wobble {

// The contact offset a scene asked for (`asked` ≥ 0), or else (negative) a tenth of the median
// spring rest length (m).  rest_lengths  #E (m);  rest_diagonal  of the rest bounding box (m)
double resolved_contact_offset(double asked, const Eigen::VectorXd& rest_lengths,
                               double rest_diagonal);

// Contact as a scene sets it up.
struct ContactParams {
  std::vector<Collider> colliders;
  double friction = 0.0;  // Coulomb coefficient μ of the material against every collider
  // Vertices are kept this far outside every collider (m), so that the triangles between them
  // do not dip into it. Negative: automatic, a tenth of the median spring rest length.
  double offset = -1.0;
};

// Vertices against colliders, with Coulomb friction, without ever touching Q.
//
// After the iterations every vertex closer than the offset to a collider is moved out along the
// surface normal by its penetration depth δ. Friction then acts on the tangential part t of its
// motion over the step relative to the collider: with μδ ≥ ‖t‖ the vertex sticks (t is undone),
// otherwise t shrinks by μδ. δ is the normal impulse Δt²·F/m the collider had to supply, so this
// is Coulomb's law with equal static and kinetic coefficients. Restitution is 0: the next step's
// velocity (pᵗ⁺ᐞᵗ − pᵗ)/Δt has no normal part into the surface.
class ColliderContact {
 public:
  ColliderContact() = default;
  // `offset` must already be resolved (not negative).
  ColliderContact(std::vector<Collider> colliders, double friction, double offset);

  void project(const StepContext& step, Eigen::MatrixXd& next);
  // The same again after something else moved `next` (self-collision): vertices it moves now are
  // added to those the last project() moved.
  void project_again(const StepContext& step, Eigen::MatrixXd& next);
  void end_step();

  const std::vector<Collider>& colliders() const { return colliders_; }
  // Collider c's translation since the last step (m): what friction measures slides against.
  const Eigen::Vector3d& motion(std::size_t c) const { return motion_[c]; }
  // Moves collider `index` rigidly; the move counts as the collider's motion over the next step
  // (so a dragged box carries a resting cloth along by friction).
  void translate(int index, const Eigen::Vector3d& offset);
  void set_friction(double friction) { friction_ = friction; }
  double friction() const { return friction_; }
  double offset() const { return offset_; }
  // Vertices moved out of a collider by the last projection.
  int contact_count() const { return contact_count_; }
  // The last project() and any project_again() after it (ms).
  double milliseconds() const { return milliseconds_; }
  // Counts as touching too each vertex flagged in `touching` (#V): those the solve held against
  // a collider (solve_contact.h), which the projection may not have had to move. After
  // project().
  void mark_pressed(const std::vector<char>& touching);
  // The same as #V flags (empty when there is no collider).
  const std::vector<char>& contact_vertices() const { return touched_; }
  bool empty() const { return colliders_.empty(); }
  // Where the projection puts vertex i found at `p` (m): out of every collider to the offset,
  // then held back by friction against its motion over the step (see the class comment).
  // `touched`, if given, is set when a collider moved it. The target of the contact term the
  // solve sees (solve_contact.h).
  Eigen::Vector3d outside_point(const StepContext& step, Eigen::Index i, Eigen::Vector3d p,
                                bool* touched = nullptr) const;

 private:
  std::vector<Collider> colliders_;
  std::vector<Eigen::Vector3d> motion_;  // each collider's translation since the last step
  void project_vertices(const StepContext& step, Eigen::MatrixXd& next);

  std::vector<char> touched_;
  double friction_ = 0.0;
  double offset_ = 0.0;
  int contact_count_ = 0;
  double milliseconds_ = 0.0;
};

}  // namespace wobble

#endif

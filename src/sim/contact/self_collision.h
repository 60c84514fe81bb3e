#ifndef WOBBLE_SIM_CONTACT_SELF_COLLISION_H
#define WOBBLE_SIM_CONTACT_SELF_COLLISION_H

#include <Eigen/Core>
#include <vector>

#include "sim/contact/self_collision_surface.h"
#include "sim/contact/self_contact_detection.h"
#include "sim/contact/self_contact_response.h"
#include "sim/contact/self_crossing_guard.h"
#include "sim/spring_network.h"

namespace wobble {

// Self-collision as a scene or the user sets it up. Off unless asked for (never on for the
// course's scenes).
struct SelfCollisionParams {
  bool on = false;
  double thickness = 0.01;  // m: the gap the surface keeps between its own layers
};

// Throws InputError unless the thickness is within limits::self_collision_thickness.
void validate_self_collision(const SelfCollisionParams& params);

// The largest thickness a mesh's surface can keep (m): 1.5 times its mean rest edge (at least
// limits::self_collision_thickness.low). A thicker gap than that would have to hold apart the
// surface's own neighbours across several edges, which its rest shape puts closer; the
// thickness used is clamped to it, and the caller says so.
double largest_self_collision_thickness(const SpringNetwork& network);

// Keeps a surface (the network's render triangles F) from passing through itself, after the
// step's iterations, without touching Q. docs: docs/method.md, "Contact, damping and wind".
//
// Each step: the pairs of features the motion can bring within the thickness are found
// (SelfContactDetection: a broad phase on the worker pool, bounded per feature), pushed apart
// along planes from the start of the step (SelfContactResponse), and the step ends with the
// crossing guard (SelfCrossingGuard). For a vertex and a triangle, the point q₀ of the triangle
// closest to the vertex v₀ at the start gives a separating plane with normal n₀ = (v₀ − q₀)/
// ‖v₀ − q₀‖ (the whole triangle lies behind it); for two edges, their closest points do the
// same. The step must keep the gap along n₀ between the same two points at least the thickness
// (a pair that starts closer opens by a tenth of it a step). Because the planes come from the
// start of the step, a vertex does not tunnel through a triangle however far it moves. When a
// push takes a vertex farther from its path than the margin, the pairs are found again along the
// pushed path. While the surface lies still or moves as a whole (a cloth sliding on the ground),
// the pairs found around it serve the next steps, until a vertex strays half a skin from where
// they were found, less the common motion.
class SelfCollision {
 public:
  SelfCollision() = default;
  // The surface is `rest.F`; vertices on no triangle take no part.
  SelfCollision(const SpringNetwork& rest, const SelfCollisionParams& params);

  // Moves `next` (#V by 3, m) so that the motion from `current` (#V by 3, pᵗ) keeps every vertex
  // `thickness` from every non-adjacent triangle, and every edge from every non-adjacent edge.
  // `inverse_mass` (#V, 1/kg) is 0 for a vertex that must not move; `friction` is μ.
  void project(const Eigen::MatrixXd& current, const Eigen::VectorXd& inverse_mass, double friction,
               Eigen::MatrixXd& next);

  // The last projection's pairs kept apart again after something else moved `next` (the
  // colliders); no new detection.
  void project_again(const Eigen::VectorXd& inverse_mass, Eigen::MatrixXd& next);
  // The step's last word, after project() (and project_again()): the crossing guard, and the
  // contact count.
  void finish(const Eigen::MatrixXd& current, const Eigen::VectorXd& inverse_mass,
              Eigen::MatrixXd& next);

  // As set; thickness() is the gap kept (m), params().thickness clamped to
  // largest_self_collision_thickness().
  const SelfCollisionParams& params() const { return params_; }
  double thickness() const { return thickness_; }
  // A new thickness: the rest neighbourhoods are found again.
  void set_thickness(double thickness);
  // Forgets the last projection's contacts and kept pairs (a reset).
  void clear();
  // Vertices the last projection moved, and the same as #V flags.
  int contact_count() const { return contact_count_; }
  const std::vector<char>& contact_vertices() const { return in_contact_; }
  // Vertex-triangle and edge-edge pairs the last projection pushed apart.
  int pair_count() const { return pair_count_; }
  // Pairs the last detection found able to touch (pushed or not).
  int candidate_count() const { return static_cast<int>(pairs_.size()); }
  // Vertices the crossing guard put back to where they started the last step.
  int undone_count() const { return undone_; }
  double detection_ms() const { return detection_ms_; }
  double response_ms() const { return response_ms_; }
  // Memory held for self-collision (bytes): the surface, its rest neighbourhood, the grids,
  // the pairs and the buffers. O(vertices) by design.
  std::size_t memory_bytes() const;

 private:
  // Whether every surface vertex of `positions` is within `reach` (m) of its path current → end.
  bool near_segments(const Eigen::MatrixXd& current, const Eigen::MatrixXd& end,
                     const Eigen::MatrixXd& positions, double reach) const;
  // Whether every surface vertex of `positions` is within `reach` (m) of reference_, once the
  // surface's common motion from there is taken out.
  bool near_reference(const Eigen::MatrixXd& positions, double reach) const;
  // Whether every surface vertex moves from `from` to `to` within `reach` (m) of their mean
  // motion.
  bool within_of_common_motion(const Eigen::MatrixXd& from, const Eigen::MatrixXd& to,
                               double reach) const;
  // pairs_ = the kept pairs, their closest points, normals and targets found again from
  // `current`.
  void refresh_pairs(const Eigen::MatrixXd& current);
  // The response, and the count of pairs pushed and their vertices.
  void respond(const Eigen::MatrixXd& current, const Eigen::VectorXd& inverse_mass, double friction,
               Eigen::MatrixXd& next);

  SelfCollisionParams params_;
  double thickness_ = 0.0;
  double largest_thickness_ = 0.0;
  SelfCollisionSurface surface_;
  RestNeighbours rest_neighbours_;
  SelfContactDetection detection_;
  SelfContactResponse response_;
  SelfCrossingGuard guard_;
  std::vector<SelfContactPair> pairs_;
  Eigen::MatrixXd solved_;                     // #V by 3: next as the solve left it
  Eigen::MatrixXd pushed_;                     // #V by 3: next after a round's response
  Eigen::MatrixXd reference_;                  // #V by 3: where the kept pairs were found
  std::vector<SelfContactPair> listed_pairs_;  // every pair near reference_, while listed_
  bool listed_ = false;
  // Where the last projection's pairs were found along: the path current → *path_end_, or
  // around reference_ (null); and whether that detection left pairs out.
  const Eigen::MatrixXd* path_end_ = nullptr;
  bool saturated_ = true, listed_saturated_ = true;
  std::vector<char> watched_;  // #V: vertices the crossing guard looks around
  int undone_ = 0;
  std::vector<char> in_contact_;
  int contact_count_ = 0;
  int pair_count_ = 0;
  double detection_ms_ = 0.0;
  double response_ms_ = 0.0;
};

}  // namespace wobble

#endif

#ifndef WOBBLE_SIM_CONTACT_SELF_COLLISION_H
#define WOBBLE_SIM_CONTACT_SELF_COLLISION_H

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

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

// Keeps a surface (the network's render triangles F) from passing through itself, after the
// step's iterations, without touching Q.
//
// Detection: each triangle's box swept over the step (from pᵗ to the solved positions, grown
// by the thickness) goes into a uniform grid rebuilt every step; each surface vertex looks up
// the cells its own swept box covers. A pair can touch only if the vertex comes within the
// thickness of the triangle during the step; pairs sharing a vertex, and pairs closer than the
// thickness in the rest shape, are skipped.
//
// Response: for each pair the closest point q₀ = Σαᵢxᵢ of the triangle to the vertex v at the
// start of the step gives a separating plane, normal n₀ = (v₀ − q₀)/‖v₀ − q₀‖ (the whole
// triangle lies behind it, q₀ being the closest point). The step's positions must keep
// (v − Σαᵢxᵢ)·n₀ ≥ thickness: a linear constraint on four vertices, enforced by projection
// (Gauss-Seidel, inverse-mass weighted, pinned vertices immovable). Because the plane comes from
// the start of the step, a vertex cannot pass through a triangle however far it moves in one
// step (no velocity clamp is needed). Coulomb friction then acts on each pair's tangential
// relative motion, as for colliders (μ the material's). The positions are the next step's
// velocity too: a pushed vertex keeps no velocity into the layer.
class SelfCollision {
 public:
  SelfCollision() = default;
  // The surface is `rest.F`; vertices on no triangle take no part.
  SelfCollision(const SpringNetwork& rest, const SelfCollisionParams& params);

  // Moves `next` (#V by 3, m) so that the motion from `current` (#V by 3, pᵗ) keeps every vertex
  // `thickness` from every non-adjacent triangle. `inverse_mass` (#V, 1/kg) is 0 for a pinned
  // vertex; `friction` is μ.
  void project(const Eigen::MatrixXd& current, const Eigen::VectorXd& inverse_mass, double friction,
               Eigen::MatrixXd& next);

  const SelfCollisionParams& params() const { return params_; }
  void set_thickness(double thickness) { params_.thickness = thickness; }
  // Forgets the last projection's contacts.
  void clear();
  // Vertices the last projection moved, and the same as #V flags.
  int contact_count() const { return contact_count_; }
  const std::vector<char>& contact_vertices() const { return in_contact_; }
  // Pairs whose constraint the last projection found within the thickness.
  int pair_count() const { return pair_count_; }
  double detection_ms() const { return detection_ms_; }
  double response_ms() const { return response_ms_; }

 private:
  struct Pair {
    int vertex;
    int triangle;
    Eigen::Vector3d alpha;   // barycentric coordinates of q₀ on the triangle
    Eigen::Vector3d normal;  // n₀
    double lambda = 0.0;     // the push applied so far along n₀ (m·kg)
  };
  void detect(const Eigen::MatrixXd& current, const Eigen::MatrixXd& next);
  void build_grid(const Eigen::MatrixXd& current, const Eigen::MatrixXd& next);

  SelfCollisionParams params_;
  Eigen::MatrixXd rest_;               // #V by 3 rest positions
  Eigen::MatrixXi triangles_;          // #F by 3
  std::vector<int> surface_vertices_;  // vertices on a triangle
  double cell_ = 1.0;                  // grid cell size (m)
  // The grid: triangle ids by cell, cells hashed into a table of `cell_start_.size() - 1` slots.
  std::vector<int> cell_start_, cell_triangles_;
  std::vector<Eigen::AlignedBox3d> boxes_;  // each triangle's swept box, grown by the thickness
  std::vector<int> large_;                  // triangles whose box covers too many cells
  std::vector<int> seen_;                   // per triangle: the last vertex that looked at it
  std::vector<Pair> pairs_;
  std::vector<char> in_contact_;
  int contact_count_ = 0;
  int pair_count_ = 0;
  double detection_ms_ = 0.0;
  double response_ms_ = 0.0;
};

}  // namespace wobble

#endif

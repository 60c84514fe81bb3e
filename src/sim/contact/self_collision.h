#ifndef WOBBLE_SIM_CONTACT_SELF_COLLISION_H
#define WOBBLE_SIM_CONTACT_SELF_COLLISION_H

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "sim/contact/spatial_grid.h"
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
// step's iterations, without touching Q. The README's "Self-collision" says what was measured.
//
// Detection: every triangle's and every edge's box, swept over the step (from pᵗ to the solved
// positions) and grown by half the thickness plus a margin for the response's pushes, goes into
// a uniform grid rebuilt every step; each surface vertex looks up the triangles near its own
// swept box, edges meet the edges near theirs. A pair is kept only if it can come within the
// thickness (plus the margins) during the step: its distance at the start less the largest
// motion of one of its vertices relative to another. Pairs sharing a vertex, and pairs closer
// than twice the thickness in the rest shape (a mesh's own neighbourhood), never count. When a
// push takes a vertex farther from its path than the margin, the pairs are found again. While
// the surface lies still, the pairs found around it serve the next steps, until a vertex strays
// half a skin from where they were found.
//
// Response: for a vertex v and a triangle, the point q₀ = Σαᵢxᵢ of the triangle closest to v at
// the start of the step gives a separating plane with normal n₀ = (v₀ − q₀)/‖v₀ − q₀‖ (the whole
// triangle lies behind it, q₀ being the closest point); for two edges, their closest points at
// the start do the same. The step's positions must keep the gap along n₀ between the same two
// points (same barycentric weights) at least the thickness (a pair that starts closer opens by
// a tenth of it a step): a linear constraint on four vertices, (Σ βₖxₖ)·n₀ ≥ target, enforced
// by Gauss-Seidel projection weighted by inverse masses (a pinned vertex does not move). Because
// the planes come from the start of the step, a vertex does not tunnel through a triangle
// however far it moves: no velocity clamp is needed. Coulomb friction (μ the material's) then
// acts on the sliding of a vertex over a triangle's face. The positions are the next step's
// velocity too: a pushed vertex keeps no velocity into the layer. The planes are first order,
// so finish() ends with a last resort (undo_crossings) that no step adds a crossing.
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
  // The step's last word, after project() (and project_again()): undo_crossings, and the
  // contact count.
  void finish(const Eigen::MatrixXd& current, const Eigen::VectorXd& inverse_mass,
              Eigen::MatrixXd& next);

  const SelfCollisionParams& params() const { return params_; }
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
  // Vertices the last resort put back to where they started the last step (counted each time).
  int undone_count() const { return undone_; }
  double detection_ms() const { return detection_ms_; }
  double response_ms() const { return response_ms_; }

 private:
  // (Σ βₖ x_{vertex[k]})·normal ≥ thickness.
  struct Pair {
    int vertex[4];
    double beta[4];
    Eigen::Vector3d normal;
    double target = 0.0;          // the gap it must keep this step (m): the thickness, or less
    double depth = 0.0;           // how far the pair was pushed apart along the normal so far (m)
    bool vertex_triangle = true;  // or edge-edge
  };
  // pairs_ = the pairs the motion current → end can bring within the thickness plus twice the
  // allowance (m).
  void detect(const Eigen::MatrixXd& current, const Eigen::MatrixXd& end, double allowance);
  // Whether every surface vertex of `positions` is within `reach` (m) of its path current → end.
  bool near_segments(const Eigen::MatrixXd& current, const Eigen::MatrixXd& end,
                     const Eigen::MatrixXd& positions, double reach) const;
  // Whether every surface vertex of `positions` is within `reach` (m) of reference_.
  bool near_reference(const Eigen::MatrixXd& positions, double reach) const;
  // pairs_ = the kept pairs, their closest points, normals and targets found again from
  // `current`.
  void refresh_pairs(const Eigen::MatrixXd& current);
  // Sweeps, friction, sweeps; counts the pairs pushed and marks their vertices.
  void respond(const Eigen::MatrixXd& current, const Eigen::VectorXd& inverse_mass, double friction,
               Eigen::MatrixXd& next);
  // The pairs closer than rest_skip_factor thicknesses in the rest shape, which never count.
  void find_rest_neighbours();
  // Each step's detection allows `margin` (m) more motion than current → next.
  void sweep_boxes(const Eigen::MatrixXd& current, const Eigen::MatrixXd& next, double margin);
  void find_vertex_triangle_pairs(const Eigen::MatrixXd& current, const Eigen::MatrixXd& next,
                                  double margin);
  void find_edge_edge_pairs(const Eigen::MatrixXd& current, const Eigen::MatrixXd& next,
                            double margin);
  // Keeps the pair when it can come within the thickness during the step. Its first
  // `first_size` vertices are one feature (the vertex, or the first edge), the rest the other.
  void keep_if_close(Pair pair, int first_size, const Eigen::MatrixXd& current,
                     const Eigen::MatrixXd& next, double margin);
  // Gauss-Seidel: one sweep over the pairs; returns the largest violation it found (m).
  double separate(const Eigen::VectorXd& inverse_mass, Eigen::MatrixXd& next);
  // The last resort: an edge of `next` that passes through a triangle it did not pass through at
  // the start (the planes are a first-order guard: a pair turning fast in one step can slip
  // past) has its two vertices, the triangle's three and their neighbours put back where they
  // started the step; repeated, looking only around what was put back, until nothing new
  // crosses. Vertices put back keep the start's freedom from crossings, so the step ends with no
  // crossing it did not start with, but one a pinned vertex (which follows its target) makes:
  // that is left to the planes, which push the cloth out of the pin's way (putting the cloth
  // back would hold it still in the pin's path).
  void undo_crossings(const Eigen::MatrixXd& current, const Eigen::VectorXd& inverse_mass,
                      Eigen::MatrixXd& next);
  // Whether edge `edge` passes through triangle `triangle` at `next` and did not at `current`
  // (the boxes in edge_boxes_ and triangle_boxes_ must be those of `next`).
  bool crosses(int edge, int triangle, const Eigen::MatrixXd& current,
               const Eigen::MatrixXd& next) const;
  void apply_friction(const Eigen::MatrixXd& current, const Eigen::VectorXd& inverse_mass,
                      double friction, Eigen::MatrixXd& next);

  SelfCollisionParams params_;
  Eigen::MatrixXd rest_;               // #V by 3 rest positions
  Eigen::MatrixXi triangles_;          // #F by 3
  Eigen::MatrixXi edges_;              // #edges by 2: each triangle edge once
  std::vector<int> surface_vertices_;  // vertices on a triangle
  SpatialGrid triangle_grid_, edge_grid_;
  std::vector<Eigen::AlignedBox3d> triangle_boxes_, edge_boxes_;  // swept, grown by the thickness
  std::vector<int> seen_triangle_;  // the stamp of the last query that looked at each triangle
  // Rest neighbourhoods as compressed rows: the triangles near each vertex, and the
  // higher-numbered edges near each edge.
  std::vector<int> rest_triangles_start_, rest_triangles_, rest_edges_start_, rest_edges_;
  std::vector<Pair> pairs_;
  Eigen::MatrixXd solved_;          // #V by 3: next as the solve left it
  Eigen::MatrixXd pushed_;          // #V by 3: next after a round's response
  Eigen::MatrixXd reference_;       // #V by 3: where the kept pairs were found
  std::vector<Pair> listed_pairs_;  // every pair near reference_, while listed_
  bool listed_ = false;
  std::vector<int> crossed_, changed_;
  std::vector<char> frozen_;
  // Incidence as compressed rows: each vertex's edges and triangles.
  std::vector<int> vertex_edges_start_, vertex_edges_, vertex_triangles_start_, vertex_triangles_;
  // Stamps: which query last looked at each triangle and edge, which round checked them.
  std::vector<int> seen_edge_, triangle_checked_, edge_checked_;
  int stamp_ = 0;
  void next_stamp();
  int undone_ = 0;
  std::vector<char> in_contact_;
  int contact_count_ = 0;
  int pair_count_ = 0;
  double detection_ms_ = 0.0;
  double response_ms_ = 0.0;
};

}  // namespace wobble

#endif

#ifndef WOBBLE_SIM_CONTACT_SELF_CONTACT_DETECTION_H
#define WOBBLE_SIM_CONTACT_SELF_CONTACT_DETECTION_H

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "sim/contact/self_collision_surface.h"
#include "sim/contact/spatial_grid.h"
#include "sim/parallel/worker_pool.h"

namespace wobble {

// Two features of the surface kept apart: a vertex and a triangle, or two edges. Their closest
// points at the start of the step are q = Σ βₖ x_{vertex[k]} (β = 1, −α for a vertex and a
// triangle's barycentric α; 1−s, s, −(1−u), −u for two edges), and the step must end with
// q·normal ≥ target.
struct SelfContactPair {
  int vertex[4];
  double beta[4];
  Eigen::Vector3d normal;
  double target = 0.0;  // m: the thickness, or less for a pair that starts closer
  double depth = 0.0;   // m: how far the response pushed it apart along the normal so far
  bool vertex_triangle = true;
};

// Finds the pairs of a surface's features that a step's motion, from `start` to `end`, can
// bring within the thickness (plus twice a margin for the response's pushes).
//
// Broad phase: the mean displacement ū of the surface over the step is taken out, so that a
// cloth falling or carried as a whole does not sweep wide boxes: each vertex wanders
// wᵥ = ‖uᵥ − ū‖ from where the common motion takes it, and two features can come closer by at
// most the sum of their vertices' largest wander. Each triangle's and edge's box at the start,
// grown by half the thickness, the margin and its wander, goes into a spatial grid whose cell
// follows the boxes' sizes; each vertex looks up the triangles its own grown box overlaps, each
// edge the higher-numbered edges. The queries run on the worker pool, in fixed chunks merged in
// order, so the pairs never depend on the thread count.
//
// Narrow phase: the closest points at the start; the pair is kept when their distance less the
// most the motion can close it (the wander bound, or each vertex's motion relative to the
// pair's first vertex, whichever is less) is under thickness + 2·margin. Pairs sharing a vertex
// and the rest shape's own neighbourhood (RestNeighbours) never count.
//
// Bounded by design: each vertex keeps its max_pairs_per_feature nearest triangles and each
// edge as many edges, among the first max_examined its query finds; the grids' memory is
// O(features) (spatial_grid.h). So the pairs are O(vertices) whatever the thickness, the rest
// shape or the overlap; only in a pile denser than that (a 1 mm ball of a whole cloth) can a
// pair go unseen, and the crossing guard (self_crossing_guard.h) still stands behind it.
class SelfContactDetection {
 public:
  static constexpr int max_pairs_per_feature = 32;
  // How much of the thickness a pair that starts too close may open up by in one step: pushed
  // out at once it would leave with the whole shortfall as speed, and a pile kept on bouncing.
  static constexpr double recovery_fraction = 0.1;
  static constexpr int max_examined = 256;
  // The most boxes a query meets, those it skips (its own neighbourhood) included.
  static constexpr int max_met = 4 * max_examined;

  //   surface, rest   the surface and its rest neighbourhood
  //   start, end      #V by 3 positions (m) where the step starts and where it is heading
  //   thickness       m: the gap to keep
  //   margin          m: how much farther than `end` the response may still push a vertex
  //   pairs           out: the pairs, vertex-triangle ones first, then edge-edge ones
  void detect(const SelfCollisionSurface& surface, const RestNeighbours& rest,
              const Eigen::MatrixXd& start, const Eigen::MatrixXd& end, double thickness,
              double margin, std::vector<SelfContactPair>& pairs);

  // Whether the last detect() left pairs out (a feature with more than max_pairs_per_feature
  // pairs, or more than max_examined candidates): the crossing guard then looks everywhere.
  bool saturated() const { return saturated_; }

  // Memory held by the buffers (bytes), for the benchmark.
  std::size_t memory_bytes() const;

 private:
  struct Chunk {
    std::vector<SelfContactPair> pairs;
    std::vector<std::pair<double, int>> near;  // one query's kept pairs: (closeness, index)
    std::vector<SelfContactPair> staged;       // one query's kept pairs
    bool saturated = false;
  };
  // The query of surface vertex `v` (vertex-triangle) or of edge `e` (edge-edge) into `chunk`.
  void query_vertex(int v, Chunk& chunk) const;
  void query_edge(int e, Chunk& chunk) const;
  // Keeps the pair in `chunk.staged` when it can come within reach.
  void keep_if_close(SelfContactPair pair, int first_size, Chunk& chunk) const;
  // Moves the nearest max_pairs_per_feature of chunk.staged to chunk.pairs.
  void commit(Chunk& chunk) const;

  // The call's inputs, for the queries.
  const SelfCollisionSurface* surface_ = nullptr;
  const RestNeighbours* rest_ = nullptr;
  const Eigen::MatrixXd* start_ = nullptr;
  const Eigen::MatrixXd* end_ = nullptr;
  double thickness_ = 0.0, margin_ = 0.0;
  Eigen::Vector3d mean_motion_ = Eigen::Vector3d::Zero();

  std::vector<double> wander_;  // #V: ‖uᵥ − ū‖ (m)
  std::vector<Eigen::AlignedBox3d> triangle_boxes_, edge_boxes_;
  std::vector<double> extents_;
  SpatialGrid triangle_grid_, edge_grid_;
  std::vector<Chunk> chunks_;
  SharingPayoff payoff_;
  bool saturated_ = false;
};

}  // namespace wobble

#endif

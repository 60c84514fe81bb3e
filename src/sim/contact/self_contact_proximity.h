#ifndef WOBBLE_SIM_CONTACT_SELF_CONTACT_PROXIMITY_H
#define WOBBLE_SIM_CONTACT_SELF_CONTACT_PROXIMITY_H

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <atomic>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "sim/contact/self_collision_surface.h"
#include "sim/contact/self_contact_pair.h"
#include "sim/contact/spatial_grid.h"
#include "sim/parallel/worker_pool.h"

namespace wobble {

// Self-contact in the manner of Offset Geometric Contact (Chen et al. 2025): at the start of an
// epoch, positions x that are free of crossings, find the surface's close pairs and, for each
// vertex, how far it may move before anything could pass through anything else.
//
// Pairs: every vertex-triangle pair (the vertex not on the triangle) and edge-edge pair (no
// shared vertex) closer than `contact_distance` at x that `rest` does not list (the rest shape's
// own neighbourhood is never contact), as SelfContactPair:
//   vertex  (v, a, b, c) for a vertex and a triangle; (p0, p1, q0, q1) for two edges, the
//           lower-numbered edge first, each edge's lower vertex first
//   beta    (1, −α_a, −α_b, −α_c) with α the barycentric closest point; (1−s, s, −(1−u), −u)
//   normal  q/‖q‖ with q = Σ βₖ xₖ, from the second feature's closest point to the first's; at a
//           distance of ~0, the triangle's face normal (vertex-triangle) or the edges' cross
//           product (edge-edge), else any vector perpendicular to the first edge, else +z
//   depth   the distance ‖q‖ at x (m): this field, not a push, in these pairs
//   target  0: left to the caller, who chooses the offset to keep
// Each vertex keeps its max_pairs_per_feature nearest triangles and each edge as many nearest
// higher-numbered edges. Vertex-triangle pairs come first, by vertex; then edge-edge, by the
// first edge's lower vertex, then by that edge.
//
// Bounds b (#V, m), with reaches R (#V, m) and γ = bound_fraction:
//   b_v = γ · max(0, min(R_v, ½ d_v, ½ min_{t ∋ v} d_t, ½ min_{e ∋ v} d_e) − ½ f)
// d_v: distance from v to its nearest found triangle not on it; d_t: from triangle t to its
// nearest found vertex not on it; d_e: from edge e to its nearest found edge sharing no vertex;
// f: a floor far below the thickness and far above rounding (floor()).
// A pair is found when its boxes at x, grown by the reaches, overlap: a vertex's point by R_v,
// a triangle's box by the largest R of its vertices, an edge's by the largest of its two (or
// nearly overlap: the triangles' and edges' boxes and reaches are kept in single precision,
// rounded outwards, so a few more pairs are found, never fewer). Every found pair counts, the
// rest neighbours and pairs beyond max_pairs_per_feature included.
// Why these bounds rule out a crossing, and how the search finds the pairs that can lower a
// bound without looking at every box in reach: docs/method.md, "Self-contact".
//
// Bounded by design: the grids and buffers are O(features) and kept between calls; a query
// looks at no more than max_met boxes. A query that meets more (coincident layers, a cloth
// crushed into a ball: a thousand features in reach) stops, and then freezes what it might have
// missed: its vertices and those of every triangle and edge whose box in a grid overlaps its query
// box get b = 0, so every pair it did not examine moves only with the common motion. Queries run on
// the worker pool in fixed chunks merged in order; the nearest distances are lowered with atomic
// minima, which give the same result in any order. So the pairs and bounds never depend on the
// thread count.
//
// Vertices on no triangle get b = +∞. A reach that is negative or not a number counts as 0, one
// beyond the diagonal of x's surface bounding box as that diagonal.
class SelfContactProximity {
 public:
  static constexpr int max_pairs_per_feature = 32;
  static constexpr int max_met = 1024;
  static constexpr double bound_fraction = 0.9;  // γ
  // The search grids' cells, in sides of the upper quartile of the triangles' filed boxes.
  static constexpr double cell_per_box = 2.0;
  // The floor f below which no pair is let come (m): this share of the contact distance, and
  // at least rounding_margin roundings of the largest coordinate (see floor()).
  static constexpr double separation_share = 1e-6;
  static constexpr double rounding_margin = 1024.0;

  // pool: where the queries run; null for WorkerPool::shared().
  explicit SelfContactProximity(WorkerPool* pool = nullptr) : pool_(pool) {}

  //   surface, rest      the surface and its rest neighbourhood (rest.find already called)
  //   x                  #V by 3 positions at the start of the epoch (m), finite
  //   reach              #V reaches R (m)
  //   contact_distance   m: pairs closer than this are listed
  //   pairs              out: the pairs, as above
  //   bounds             out: #V bounds b (m)
  void find(const SelfCollisionSurface& surface, const RestNeighbours& rest,
            const Eigen::MatrixXd& x, const Eigen::VectorXd& reach, double contact_distance,
            std::vector<SelfContactPair>& pairs, Eigen::VectorXd& bounds);

  // The last find()'s floor f (m): every bound is γ/2 × max(0, its nearest distance − f), so a
  // found pair at distance d ≥ f stays at least γf apart. Without it a pair pressed together
  // comes, epoch after epoch, within the rounding of the coordinates of touching, where rounding
  // alone carries an edge through a triangle (the sphere wrap crossed itself so, every vertex
  // within its bound, pairs 10⁻¹⁶ m apart at coordinates of 3 m).
  double floor() const { return floor_; }
  // Whether the last find() had a query meet more than max_met boxes (and so froze vertices).
  bool saturated() const { return saturated_; }
  // Whether the last find()'s bounds keep every pair from crossing: no query stopped (the pairs
  // among frozen vertices went unexamined) and no found pair was closer than the floor (where
  // rounding may decide).
  bool covers_every_pair() const { return !saturated_ && !under_floor_; }
  // Memory held by the buffers (bytes).
  std::size_t memory_bytes() const;

 private:
  // One feature's nearest pairs so far.
  struct Kept {
    std::vector<std::pair<double, int>> near;  // a max-heap of (distance, slot)
    std::vector<SelfContactPair> staged;       // the slots, at most max_pairs_per_feature
  };
  struct Chunk {
    std::vector<SelfContactPair> pairs;
    std::vector<Kept> kept;                   // one per feature of the query
    std::vector<int> owned;                   // the edges of an edge query
    std::vector<Eigen::AlignedBox3d> boxes;   // their bare boxes
    std::vector<double> ends;                 // their upper vertices' nearest so far (m)
    std::vector<Eigen::AlignedBox3d> frozen;  // query boxes of the queries that stopped
  };
  // A triangle or an edge: the largest reach of its vertices (m), rounded up to single
  // precision, and its vertices (an edge's third is −1). Its box is in its grid: a query
  // measures a candidate's gap against its box as filed there (outwards to single precision,
  // grown by its need beyond the floor), which is never nearer than the bare box is, so the
  // search only looks at a few more candidates.
  struct Feature {
    float reach;
    int vertex[3];
  };
  WorkerPool& pool() const { return pool_ ? *pool_ : WorkerPool::shared(); }
  static Eigen::AlignedBox3d grown(Eigen::AlignedBox3d box, double by) {
    box.min().array() -= by;
    box.max().array() += by;
    return box;
  }
  // A feature's bare box at x, and its need: the largest of its vertices' (need_).
  Eigen::AlignedBox3d box(const Feature& feature) const;
  double need(const Feature& feature) const;
  // A feature's box for its grid: grown by its need's excess over the floor of its queries.
  Eigen::AlignedBox3d filed(const Feature& feature, double floor) const {
    return grown(box(feature), std::max(need(feature) - floor, 0.0));
  }
  // How far apart two boxes are along each axis (0 where they overlap on it).
  static Eigen::Array3d box_gap(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b) {
    return (a.min().array() - b.max().array()).max(b.min().array() - a.max().array()).max(0.0);
  }
  void prepare(const Eigen::MatrixXd& x, const Eigen::VectorXd& reach);
  // need_[v] = v's seed: an upper bound on v's nearest found distance, from its mesh
  // neighbourhood alone.
  void seed_vertex(int v);
  void query_vertex(int v, Chunk& chunk);
  // The edges whose lower vertex is v, against the higher-numbered edges.
  void query_edges(int v, Chunk& chunk);
  // Edges e < f, with e's bare box and f's filed one: their distance lowers the four vertices'
  // nearest (own0, own1 for e's, held locally), and the pair is offered to e's kept pairs.
  void examine_edges(int e, const Eigen::AlignedBox3d& e_box, int f,
                     const Eigen::AlignedBox3d& f_box, double& own0, double& own1, Kept& kept);
  // Offers a pair at `distance` to a feature's nearest max_pairs_per_feature.
  void stage(const SelfContactPair& pair, double distance, Kept& kept) const;
  // Appends the kept pairs to `pairs`, in the order of the other feature's vertices.
  void commit(Kept& kept, std::vector<SelfContactPair>& pairs) const;
  void freeze_near_saturated_queries(double cell);
  // The nearest found distance of vertex v so far (m); lowered, never raised, from any thread.
  void lower(int v, double distance) {
    std::atomic<double>& slot = nearest_[v];
    double current = slot.load(std::memory_order_relaxed);
    while (distance < current &&
           !slot.compare_exchange_weak(current, distance, std::memory_order_relaxed)) {
    }
  }
  double nearest(int v) const { return nearest_[v].load(std::memory_order_relaxed); }

  WorkerPool* pool_;
  // The call's inputs, for the queries.
  const SelfCollisionSurface* surface_ = nullptr;
  const RestNeighbours* rest_ = nullptr;
  double contact_distance_ = 0.0;

  std::vector<Eigen::Vector3d> points_;  // #V: x row by row, packed (m)
  std::vector<double> reach_;            // #V: R, made safe (m)
  // #V: what a vertex's pairs must be closer than to matter (m): its seed, min(2R_v, some found
  // pair's distance), for the vertex queries; its nearest after them, for the edge queries.
  std::vector<double> need_;
  std::vector<Feature> triangles_, edges_;
  // What a query box grows by at least (m): the contact distance, or most vertices' needs (the
  // seeds for the vertex queries, the nearest after them for the edge queries).
  double vertex_floor_ = 0.0, edge_floor_ = 0.0;
  std::vector<double> scratch_;
  // The features' filed boxes (grown by their needs beyond the floor), and the stopped queries'.
  SpatialGrid triangle_grid_, edge_grid_, frozen_grid_;
  // #V: min(seed, the nearest found distance): b_v = γ/2 × it.
  std::unique_ptr<std::atomic<double>[]> nearest_;
  std::size_t nearest_capacity_ = 0;
  std::vector<Eigen::AlignedBox3d> frozen_boxes_;
  std::vector<char> feature_frozen_;  // #F + #E
  std::vector<Chunk> chunks_;
  SharingPayoff vertex_payoff_, edge_payoff_, seed_payoff_, frozen_payoff_;
  bool saturated_ = false, under_floor_ = false;
  double floor_ = 0.0;
};

// Moves p so that every vertex v with a finite bound satisfies ‖(p_v − x_v) − common‖ ≤ b_v, by
// scaling that relative displacement down: p_v = x_v + common + s·(p_v − x_v − common), s < 1.
// A bound that is negative or not a number counts as 0; a displacement that is not finite
// becomes the common motion alone. O(#V), allocates nothing.
//
//   x       #V by 3 positions at the start of the epoch (m)
//   common  the epoch's common motion (m)
//   bounds  #V bounds (m), as SelfContactProximity::find gives them
//   p       #V by 3 positions (m), changed in place
// Returns how many vertices it moved.
int clamp_to_bounds(const Eigen::MatrixXd& x, const Eigen::Vector3d& common,
                    const Eigen::VectorXd& bounds, Eigen::MatrixXd& p);

}  // namespace wobble

#endif

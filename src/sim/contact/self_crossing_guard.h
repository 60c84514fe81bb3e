#ifndef WOBBLE_SIM_CONTACT_SELF_CROSSING_GUARD_H
#define WOBBLE_SIM_CONTACT_SELF_CROSSING_GUARD_H

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "sim/contact/self_collision_surface.h"
#include "sim/contact/spatial_grid.h"
#include "sim/parallel/worker_pool.h"

namespace wobble {

// The last resort behind the contact planes, which are a first-order guard (a pair turning fast
// in one step can slip past): an edge of `next` that passes through a triangle it did not pass
// through at `current` has its two vertices, the triangle's three and their neighbours put back
// where they started the step; repeated, looking only around what was put back, until nothing
// new crosses. Vertices put back keep the start's freedom from crossings, so the step ends with
// no crossing it did not start with, but one with a pinned vertex in it (a pin follows its
// target, and putting ever more of the cloth back would hold it still in the pin's path): such a
// crossing's free vertices and their neighbours are put back once, at the end, and kept there
// only if that ends it without making another; else it is left to the planes, which push the
// cloth out of the pin's way.
//
// The first round looks at every edge against the triangles near it, on the worker pool in fixed
// chunks (the same crossings in the same order on any thread count); the grids are
// O(features), built as the detection's (spatial_grid.h).
class SelfCrossingGuard {
 public:
  //   current       #V by 3 positions where the step started (m)
  //   inverse_mass  #V, 1/kg: 0 for a vertex that follows a target
  //   next          #V by 3 positions where it ends (m), vertices put back
  //   put_back      #V flags, set for each vertex put back
  //   watched       #V flags, or null: the first round looks only at the edges and triangles
  //                 with a flagged vertex (the caller knows no other pair came near: every
  //                 crossing starts as a vertex and a triangle, or two edges, coming within
  //                 the thickness, which the detection lists); null looks at every edge
  // Returns how many vertices were put back.
  int undo_crossings(const SelfCollisionSurface& surface, const Eigen::MatrixXd& current,
                     const Eigen::VectorXd& inverse_mass, Eigen::MatrixXd& next,
                     std::vector<char>& put_back, const std::vector<char>* watched = nullptr);

  std::size_t memory_bytes() const;

 private:
  // Whether edge `edge` passes through triangle `triangle` at `next` and did not at `current`.
  bool crosses(const SelfCollisionSurface& surface, int edge, int triangle,
               const Eigen::MatrixXd& current, const Eigen::MatrixXd& next) const;
  // The grids of the features with a watched vertex (every feature when `watched` is null).
  void build_grids(const SelfCollisionSurface& surface, const Eigen::MatrixXd& next,
                   const std::vector<char>* watched = nullptr);
  // The listed crossings with a pinned vertex, tried once each; returns the vertices put back.
  int resolve_pinned(const SelfCollisionSurface& surface, const Eigen::MatrixXd& current,
                     const Eigen::VectorXd& inverse_mass, Eigen::MatrixXd& next,
                     std::vector<char>& put_back);

  std::vector<Eigen::AlignedBox3d> triangle_boxes_, edge_boxes_;
  SpatialGrid triangle_grid_, edge_grid_;
  std::vector<std::vector<int>> chunk_crossed_;
  std::vector<int> crossed_, found_, changed_, edge_checked_, triangle_checked_;
  std::vector<std::pair<int, int>> pinned_crossings_;  // (edge, triangle)
  std::vector<std::pair<int, Eigen::Vector3d>> saved_;
  std::vector<char> frozen_;
  SharingPayoff payoff_;
};

}  // namespace wobble

#endif

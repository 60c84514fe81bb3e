#ifndef WOBBLE_SIM_CONTACT_SELF_COLLISION_SURFACE_H
#define WOBBLE_SIM_CONTACT_SELF_COLLISION_SURFACE_H

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "sim/spring_network.h"

namespace wobble {

// Lists of ids per owner as compressed rows: owner o's ids are ids[start[o]] .. ids[start[o+1]−1].
struct CompressedRows {
  std::vector<int> start{0}, ids;
  int begin(int owner) const { return start[owner]; }
  int end(int owner) const { return start[owner + 1]; }
  // Whether `id` is among owner's ids, which must be sorted.
  bool contains(int owner, int id) const;
  std::size_t memory_bytes() const { return (start.capacity() + ids.capacity()) * sizeof(int); }
};

// The surface self-collision keeps apart: the network's render triangles and their edges, and
// which vertex is on which.
struct SelfCollisionSurface {
  SelfCollisionSurface() = default;
  explicit SelfCollisionSurface(const SpringNetwork& rest);

  Eigen::MatrixXd rest;         // #V by 3 rest positions (m)
  Eigen::MatrixXi triangles;    // #F by 3
  Eigen::MatrixXi edges;        // #edges by 2: each triangle edge once, lower index first
  std::vector<int> vertices;    // the vertices on a triangle, in order
  CompressedRows vertex_edges;  // each vertex's edges
  CompressedRows vertex_triangles;
  double mean_edge = 0.0;  // m, of the rest shape
  double size = 0.0;       // m: the rest shape's bounding-box diagonal
};

// The pairs the rest shape holds closer than a reach (twice the thickness): a mesh's own
// neighbourhood (the next vertex along a pleat, a seam), never contact. Decided when asked, from
// the rest positions, so nothing is stored and a crumpled or coincident rest shape costs no
// memory: a pair is a rest neighbour when its features' distance in the rest shape is below the
// reach (0: none is).
class RestNeighbours {
 public:
  RestNeighbours() = default;  // none
  RestNeighbours(const SelfCollisionSurface& surface, double reach);
  // surface: the one given to the constructor.
  bool vertex_triangle(const SelfCollisionSurface& surface, int vertex, int triangle) const;
  bool edge_edge(const SelfCollisionSurface& surface, int e, int f) const;
  std::size_t memory_bytes() const { return rest_.capacity() * sizeof(Eigen::Vector3d); }

 private:
  double reach_ = 0.0;
  std::vector<Eigen::Vector3d> rest_;  // the rest positions row by row, packed (m)
};

}  // namespace wobble

#endif

#ifndef WOBBLE_SIM_CONTACT_SELF_COLLISION_SURFACE_H
#define WOBBLE_SIM_CONTACT_SELF_COLLISION_SURFACE_H

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "sim/contact/spatial_grid.h"
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
// neighbourhood (the next vertex along a pleat, a seam), never contact. Bounded: each vertex
// keeps its max_per_owner nearest triangles and each edge its max_per_owner nearest
// higher-numbered edges, among the first max_examined it finds, so a crumpled or coincident
// rest shape fills neither the memory nor the time.
class RestNeighbours {
 public:
  static constexpr int max_per_owner = 64;
  static constexpr int max_examined = 512;

  void find(const SelfCollisionSurface& surface, double reach);
  bool vertex_triangle(int vertex, int triangle) const {
    return triangles_.contains(vertex, triangle);
  }
  // e < f
  bool edge_edge(int e, int f) const { return edges_.contains(e, f); }
  std::size_t memory_bytes() const;

 private:
  CompressedRows triangles_, edges_;
};

// Keeps at most `count` of `candidates` (distance, id), the nearest, then sorts their ids into
// `ids` (appended). Used wherever a list per owner must stay bounded.
void keep_nearest(std::vector<std::pair<double, int>>& candidates, int count,
                  std::vector<int>& ids);

}  // namespace wobble

#endif

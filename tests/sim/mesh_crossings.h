#ifndef WOBBLE_TESTS_SIM_MESH_CROSSINGS_H
#define WOBBLE_TESTS_SIM_MESH_CROSSINGS_H

#include <Eigen/Core>
#include <utility>
#include <vector>

namespace wobble::testing {

// Counts the places where a triangle mesh passes through itself: pairs (edge, triangle) of the
// same mesh where the edge shares no vertex with the triangle and the segment passes through the
// closed triangle: its two ends lie on opposite sides of the triangle's plane, each farther than
// δ = 1e-9 × the diagonal of the mesh's bounding box, and the line through them meets the
// triangle or its boundary. A test helper for self-collision, written apart from the simulator's
// own code.
//
//   V          #V by 3 vertex positions (m)
//   F          #F by 3 triangles, indices into rows of V
//   crossings  if given, receives every crossing as (edge, triangle): edge a row of `edges`,
//              triangle a row of F; sorted by edge, then triangle
//   edges      if given, receives the #E by 2 unique undirected edges of F, smaller vertex first,
//              in lexicographic order
//
// Touching does not count: a segment that ends on the triangle (within δ of its plane), or lies
// in its plane, crosses nothing, so a flat sheet however turned, or two coinciding flat layers,
// report none; neither does a degenerate (zero-area) triangle. Passing exactly through the
// triangle's boundary does count (a segment through the shared edge of two triangles crosses
// both). The tests are orientation determinants o(a,b,c,d) = (b−a)·((c−a)×(d−a)) in double,
// each evaluated with its points in a fixed order (by vertex index) so that two triangles
// sharing an edge see the same signs.
//
// Broad phase: a uniform grid of cells about one mean edge long holding each triangle's bounding
// box; each edge tests only the triangles in the cells its own box covers. About linear in the
// size of the mesh when the mesh has no large clusters of overlapping triangles.
long count_mesh_crossings(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                          std::vector<std::pair<int, int>>* crossings = nullptr,
                          Eigen::MatrixXi* edges = nullptr);

}  // namespace wobble::testing

#endif

#ifndef WOBBLE_TESTS_SIM_MESH_CROSSINGS_H
#define WOBBLE_TESTS_SIM_MESH_CROSSINGS_H

#include <Eigen/Core>
#include <utility>
#include <vector>

namespace wobble::testing {

// Counts the places where a triangle mesh passes through itself: pairs (edge, triangle) of the
// same mesh where the edge shares no vertex with the triangle and the closed segment meets the
// closed triangle. A test helper for self-collision, written apart from the simulator's own code.
//
//   V          #V by 3 vertex positions (m)
//   F          #F by 3 triangles, indices into rows of V
//   crossings  if given, receives every crossing as (edge, triangle): edge a row of `edges`,
//              triangle a row of F; sorted by edge, then triangle
//   edges      if given, receives the #E by 2 unique undirected edges of F, smaller vertex first,
//              in lexicographic order
//
// Touching counts: a segment that ends on the triangle, or passes exactly through its boundary,
// crosses it (so a segment through a shared edge of two triangles crosses both). A segment lying
// in the triangle's plane never counts, and neither does a degenerate (zero-area) triangle: a
// flat sheet, or two coinciding flat layers, report no crossing. The tests are orientation
// determinants o(a,b,c,d) = (b−a)·((c−a)×(d−a)) in double, each evaluated with its points in a
// fixed order (by vertex index) so that two triangles sharing an edge see the same signs, and
// each taken as 0 within |o| ≤ 1e-12·‖b−a‖‖c−a‖‖d−a‖ (a point that close to a plane or line is
// on it: touching, or coplanar for a whole segment), so a rotated flat sheet stays flat.
//
// Broad phase: a uniform grid of cells about one mean edge long holding each triangle's bounding
// box; each edge tests only the triangles in the cells its own box covers. About linear in the
// size of the mesh when the mesh has no large clusters of overlapping triangles.
long count_mesh_crossings(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                          std::vector<std::pair<int, int>>* crossings = nullptr,
                          Eigen::MatrixXi* edges = nullptr);

}  // namespace wobble::testing

#endif

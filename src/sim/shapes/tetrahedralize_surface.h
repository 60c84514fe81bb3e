#ifndef WOBBLE_SIM_TETRAHEDRALIZE_SURFACE_H
#define WOBBLE_SIM_TETRAHEDRALIZE_SURFACE_H

#include <Eigen/Core>

namespace wobble {

// Fill the inside of a closed triangle surface with tetrahedra, so that a surface mesh (an OBJ)
// can be simulated as a jelly.
//
// 1. A grid of cubic cells of side h = (longest bounding-box side) / resolution, centred on the
//    bounding box, covers the surface: `resolution` cells along the longest side, as many as
//    needed (at least one) along the others.
// 2. A cell is kept when its centre is inside: |w| > 1/2, where w is the generalized winding
//    number, w(p) = Σ Ω_f(p) / 4π summed over the solid angles the triangles subtend at p. It
//    needs no ray casting, so it has no degenerate hits; |w| makes the result the same for an
//    inward- or outward-facing surface.
// 3. Each kept cell is split into 6 tetrahedra around its (0,0,0)–(1,1,1) diagonal (the
//    Freudenthal–Kuhn split of make_jelly_block), which matches face for face across cells.
//    Grid vertices that no kept cell uses are dropped.
// 4. Each boundary vertex (a corner of a triangle of tet_mesh_boundary_faces) moves towards the
//    closest point on the surface, at most about 0.87 h away, nearest first, but only as far
//    as keeps every tetrahedron at 10% or more of its unsnapped volume h³/6 (volume is linear
//    in one corner's position, so that distance is exact). Vertices stopped short are retried
//    twice after their neighbours have moved. So no tetrahedron inverts or flattens, at the
//    price of some boundary vertices off the surface, by up to about 0.3 h, where four
//    corners of one tetrahedron would land on nearly the same plane; the mesh's bounding box
//    can therefore stick out past the surface's by that much. On a sphere at resolution 12,
//    86% of boundary vertices end on the surface and the volume is 0.987 of the enclosed one.
//
// Complexity: step 2 is O(C·#F) for C ≤ resolution³ cells (brute force, no hierarchy) and
// step 4 is O(B·#F) for B ≈ 6·resolution² boundary vertices; memory is O(resolution³). For
// the 1280-triangle assets/meshes/blob.obj, resolution 12 takes about 0.06 s (4680 tets),
// 20 about 0.2-0.3 s (21456 tets) and 30 about 1 s (72348 tets) in a Release build on one core
// of the 2-core development machine; step 2 is most of it.
//
// Limits: features thinner than about one cell vanish or become one cell thick; cells joined
// only along an edge or at a corner stay joined there (the mesh is valid for simulation, but
// its boundary is not a manifold at such places); disconnected pieces stay disconnected; all
// tetrahedra have the same size before snapping (no grading).
//
// Throws InputError, naming what is wrong, unless V is #V by 3 and finite, F is #F by 3 with
// indices into V and no repeated corner, resolution is 1 to 1000 (indices are int), and the
// surface is closed (every edge in exactly two triangles), manifold and consistently oriented
// (each edge used once in each direction); and when no cell centre is inside.
//
// Inputs:
//   V           #V by 3 list of surface vertex positions (m)
//   F           #F by 3 list of triangles, indices into rows of V
//   resolution  cells along the longest side of the bounding box
// Outputs:
//   TV  #TV by 3 list of tetrahedral mesh vertex positions (m)
//   TT  #TT by 4 list of tetrahedra, indices into rows of TV, each positively oriented:
//       (b−a)·((c−a)×(d−a)) > 0
void tetrahedralize_surface(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, int resolution,
                            Eigen::MatrixXd& TV, Eigen::MatrixXi& TT);

// The work of step 2 before it is done: cells of the grid times `triangles`, the cell-triangle
// pairs whose solid angles are summed (0 for an empty V). Callers refuse a fill above
// limits::max_fill_pairs (sim/value_limits.h) with this number, before any time is spent.
double tetrahedralize_surface_pairs(const Eigen::MatrixXd& V, Eigen::Index triangles,
                                    int resolution);

}  // namespace wobble

#endif

#ifndef WOBBLE_RENDER_VERTEX_NORMALS_H
#define WOBBLE_RENDER_VERTEX_NORMALS_H

namespace wobble {

// Smooth per-vertex normals for shading, recomputed every frame from plain arrays.
//   positions   #V by 3, row-major xyz
//   triangles   #F by 3, row-major vertex indices, counter-clockwise seen from the front
//   normals     #V by 3 output, row-major: the area-weighted mean of the adjacent face normals,
//               normalized; a vertex on no triangle (or only degenerate ones) gets +y
// Allocates nothing, so it can run on every frame.
void compute_vertex_normals(const float* positions, int vertex_count, const unsigned* triangles,
                            int triangle_count, float* normals);

}  // namespace wobble

#endif

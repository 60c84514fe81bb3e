#include "vertex_normals.h"

#include <cmath>

namespace wobble {

void compute_vertex_normals(const float* positions, int vertex_count, const unsigned* triangles,
                            int triangle_count, float* normals) {
  for (int i = 0; i < 3 * vertex_count; ++i)
    normals[i] = 0.0f;
  for (int f = 0; f < triangle_count; ++f) {
    const unsigned* corner = triangles + 3 * f;
    const float* a = positions + 3 * corner[0];
    const float* b = positions + 3 * corner[1];
    const float* c = positions + 3 * corner[2];
    const float u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const float v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    // The unnormalized cross product is twice the area times the unit normal: the area weight
    // comes for free.
    const float n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                        u[0] * v[1] - u[1] * v[0]};
    for (int k = 0; k < 3; ++k) {
      float* target = normals + 3 * corner[k];
      target[0] += n[0];
      target[1] += n[1];
      target[2] += n[2];
    }
  }
  for (int i = 0; i < vertex_count; ++i) {
    float* n = normals + 3 * i;
    const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (length > 0.0f && std::isfinite(length)) {
      n[0] /= length;
      n[1] /= length;
      n[2] /= length;
    } else {
      n[0] = 0.0f;
      n[1] = 1.0f;
      n[2] = 0.0f;
    }
  }
}

}  // namespace wobble

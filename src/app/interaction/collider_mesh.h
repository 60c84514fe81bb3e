#ifndef WOBBLE_APP_INTERACTION_COLLIDER_MESH_H
#define WOBBLE_APP_INTERACTION_COLLIDER_MESH_H

#include <Eigen/Core>
#include <vector>

#include "sim/contact/collider.h"

namespace wobble {

// Triangles of solid colliders, as plain arrays the renderer takes (render/renderer.h's
// SolidMesh). No GL: a pure function of the colliders.
struct ColliderTriangles {
  std::vector<float> positions;     // #V by 3, row-major (m)
  std::vector<float> normals;       // #V by 3 outward unit normals
  std::vector<unsigned> triangles;  // #F by 3 indices into the rows, counter-clockwise from outside
  int vertex_count() const { return static_cast<int>(positions.size() / 3); }
  int triangle_count() const { return static_cast<int>(triangles.size() / 3); }
};

// Appends the triangles of `collider` where it is now to `mesh`:
//   sphere, capsule  rings of `segments` vertices around the axis, `segments`/4 rings from each
//                    pole to the equator (a sphere is a capsule whose ends meet)
//   box              six flat faces, two triangles each
//   plane            a square of half edge `plane_half_extent` (m), centred at the point of the
//                    plane nearest `plane_focus`, two triangles
//   ground           nothing: the viewer draws it as the ground grid
void append_collider_triangles(const Collider& collider, const Eigen::Vector3f& plane_focus,
                               float plane_half_extent, ColliderTriangles& mesh, int segments = 32);

// Every collider's triangles, in one mesh.
ColliderTriangles collider_triangles(const std::vector<Collider>& colliders,
                                     const Eigen::Vector3f& plane_focus, float plane_half_extent);

}  // namespace wobble

#endif

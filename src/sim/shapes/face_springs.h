#ifndef WOBBLE_SIM_FACE_SPRINGS_H
#define WOBBLE_SIM_FACE_SPRINGS_H

#include <Eigen/Core>
#include <vector>

namespace wobble {

// The springs of a polygon mesh as the graphics course builds them. A face of three or more
// vertices joins every pair of its vertices, so a triangle gives 3 springs, a quad 6 (its 4 edges
// and both diagonals) and an n-gon n(n−1)/2, and a pair shared by several such faces is one
// spring (the course's igl::edges). A face of two vertices (an OBJ `f i j`, or a segment of an `l`
// line) is a spring as written: the course takes a file of two-vertex faces as its spring list
// itself (E = F), so a repeated one is a second spring, which doubles that pair's stiffness in
// Q = k AᵀA + M/Δt² + w CᵀC.
//
// Inputs:
//   faces  #faces lists of 0-based vertex indices, each with at least 2 distinct vertices
// Returns:
//   E  #E by 2 springs: first the pairs of the faces of 3 or more vertices, each once as [i j]
//      with i < j, rows sorted (by i, then j), so their order depends only on the set of pairs;
//      then one row per two-vertex face, in the order of `faces` and as written ([j i] stays
//      [j i]), so a mesh of only two-vertex faces gives E = faces exactly
// Throws InputError for a face with fewer than 2 vertices, a negative index or a vertex used
// twice in one face.
Eigen::MatrixXi face_springs(const std::vector<std::vector<int>>& faces);

// Render triangles of a polygon mesh: each face with n ≥ 3 vertices [v0 v1 … vn−1] becomes the
// fan (v0, vj, vj+1) for j = 1 … n−2, which keeps the face's winding. Faces of two vertices are
// springs only and give no triangle.
//
// Inputs:
//   faces  #faces lists of 0-based vertex indices
// Returns:
//   F  #F by 3 triangles, faces in order, Σ(n−2) over faces with n ≥ 3 (0 by 3 if none)
Eigen::MatrixXi fan_triangles(const std::vector<std::vector<int>>& faces);

}  // namespace wobble

#endif

#ifndef WOBBLE_SIM_FACE_SPRINGS_H
#define WOBBLE_SIM_FACE_SPRINGS_H

#include <Eigen/Core>
#include <vector>

namespace wobble {

// The springs of a polygon mesh as the graphics course builds them: one spring between every
// pair of vertices of each face, so a triangle gives 3 springs, a quad 6 (its 4 edges and both
// diagonals) and an n-gon n(n−1)/2. A face of two vertices (or a segment of an OBJ `l` line)
// gives one spring. A pair shared by several faces is one spring.
//
// Inputs:
//   faces  #faces lists of 0-based vertex indices, each with at least 2 distinct vertices
// Returns:
//   E  #E by 2 springs [i j] with i < j, rows sorted (by i, then j), so the order depends only
//      on the set of pairs and not on the order of the faces
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

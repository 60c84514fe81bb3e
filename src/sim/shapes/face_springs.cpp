#include "face_springs.h"

#include <algorithm>
#include <string>
#include <utility>

#include "sim/input_error.h"

namespace wobble {

namespace {

void check_face(const std::vector<int>& face, std::size_t f) {
  if (face.size() < 2) {
    throw InputError("face " + std::to_string(f) + " has " + std::to_string(face.size()) +
                     " vertices, expected at least 2");
  }
  for (std::size_t a = 0; a < face.size(); ++a) {
    if (face[a] < 0) {
      throw InputError("face " + std::to_string(f) + " refers to vertex " +
                       std::to_string(face[a]) + ", expected a non-negative index");
    }
    for (std::size_t b = a + 1; b < face.size(); ++b) {
      if (face[a] == face[b]) {
        throw InputError("face " + std::to_string(f) + " uses vertex " + std::to_string(face[a]) +
                         " twice, which would make a spring of zero rest length");
      }
    }
  }
}

}  // namespace

Eigen::MatrixXi face_springs(const std::vector<std::vector<int>>& faces) {
  std::vector<std::pair<int, int>> pairs, written;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const std::vector<int>& face = faces[f];
    check_face(face, f);
    if (face.size() == 2) {
      written.emplace_back(face[0], face[1]);
      continue;
    }
    for (std::size_t a = 0; a < face.size(); ++a) {
      for (std::size_t b = a + 1; b < face.size(); ++b)
        pairs.emplace_back(std::min(face[a], face[b]), std::max(face[a], face[b]));
    }
  }
  // Sorting then dropping repeats is what makes a pair shared by two polygons one spring, and
  // makes their order independent of the face order. Two-vertex faces are the course's spring
  // list as written (E = F when every face has two vertices), so they are neither sorted nor
  // merged: a repeated one is a second spring there too.
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  pairs.insert(pairs.end(), written.begin(), written.end());

  Eigen::MatrixXi E(static_cast<Eigen::Index>(pairs.size()), 2);
  for (std::size_t e = 0; e < pairs.size(); ++e) {
    E(static_cast<Eigen::Index>(e), 0) = pairs[e].first;
    E(static_cast<Eigen::Index>(e), 1) = pairs[e].second;
  }
  return E;
}

Eigen::MatrixXi fan_triangles(const std::vector<std::vector<int>>& faces) {
  Eigen::Index count = 0;
  for (const std::vector<int>& face : faces) {
    if (face.size() >= 3) count += static_cast<Eigen::Index>(face.size()) - 2;
  }
  Eigen::MatrixXi F(count, 3);
  Eigen::Index row = 0;
  for (const std::vector<int>& face : faces) {
    for (std::size_t j = 1; j + 1 < face.size(); ++j) {
      F.row(row++) << face[0], face[j], face[j + 1];
    }
  }
  return F;
}

}  // namespace wobble

#include "render/vertex_normals.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

// Two triangles making the unit square in the xz plane, counter-clockwise seen from +y.
const std::vector<float> square = {0, 0, 0, 1, 0, 0, 0, 0, 1, 1, 0, 1};
const std::vector<unsigned> facing_up = {0, 2, 1, 1, 2, 3};

std::vector<float> normals_of(const std::vector<float>& positions,
                              const std::vector<unsigned>& triangles) {
  std::vector<float> normals(positions.size(), -7.0f);
  wobble::compute_vertex_normals(positions.data(), static_cast<int>(positions.size() / 3),
                                 triangles.data(), static_cast<int>(triangles.size() / 3),
                                 normals.data());
  return normals;
}

TEST(VertexNormals, FlatSheetPointsAlongItsWinding) {
  const std::vector<float> up = normals_of(square, facing_up);
  for (int i = 0; i < 4; ++i) {
    EXPECT_FLOAT_EQ(up[3 * i + 0], 0.0f);
    EXPECT_FLOAT_EQ(up[3 * i + 1], 1.0f);
    EXPECT_FLOAT_EQ(up[3 * i + 2], 0.0f);
  }
  const std::vector<unsigned> facing_down = {0, 1, 2, 1, 3, 2};
  const std::vector<float> down = normals_of(square, facing_down);
  for (int i = 0; i < 4; ++i)
    EXPECT_FLOAT_EQ(down[3 * i + 1], -1.0f);
}

TEST(VertexNormals, AreWeightedByTriangleArea) {
  // Vertex 0 is shared by a large triangle facing +y and a small one facing +x: the normal leans
  // towards the large one in proportion to the areas (2 and 0.5).
  const std::vector<float> positions = {0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 1, 0, 0, 0, -1};
  const std::vector<unsigned> triangles = {0, 2, 1, 0, 3, 4};
  const std::vector<float> n = normals_of(positions, triangles);
  const float length = std::sqrt(2.0f * 2.0f + 0.5f * 0.5f);
  EXPECT_NEAR(n[0], -0.5f / length, 1e-6f);  // the small face faces -x
  EXPECT_NEAR(n[1], 2.0f / length, 1e-6f);
  EXPECT_NEAR(n[2], 0.0f, 1e-6f);
}

TEST(VertexNormals, LooseAndDegenerateVerticesGetUp) {
  // Vertex 3 is on no triangle; vertices 0-2 are on a zero-area one.
  const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 2, 0, 0, 5, 5, 5};
  const std::vector<float> n = normals_of(positions, {0, 1, 2});
  for (int i = 0; i < 4; ++i) {
    EXPECT_FLOAT_EQ(n[3 * i + 0], 0.0f);
    EXPECT_FLOAT_EQ(n[3 * i + 1], 1.0f);
    EXPECT_FLOAT_EQ(n[3 * i + 2], 0.0f);
  }
}

}  // namespace

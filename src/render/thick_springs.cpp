#include "thick_springs.h"

#include <algorithm>

namespace wobble {

namespace {

constexpr GLuint spring_from_location = 0, spring_to_location = 1, spring_color_location = 2;
// Each spring's four corners carry the same row: its two ends and its colour.
constexpr int floats_per_corner = 9, floats_per_spring = 4 * floats_per_corner;

}  // namespace

ThickSprings::ThickSprings() {
  glGenVertexArrays(1, &array_);
  glGenBuffers(1, &buffer_);
  glGenBuffers(1, &indices_);
  glBindVertexArray(array_);
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  const GLsizei stride = floats_per_corner * sizeof(float);
  const GLuint locations[3] = {spring_from_location, spring_to_location, spring_color_location};
  for (int k = 0; k < 3; ++k) {
    glEnableVertexAttribArray(locations[k]);
    glVertexAttribPointer(locations[k], 3, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(3 * k * sizeof(float)));
  }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_);
  glBindVertexArray(0);
}

ThickSprings::~ThickSprings() {
  glDeleteBuffers(1, &indices_);
  glDeleteBuffers(1, &buffer_);
  glDeleteVertexArrays(1, &array_);
}

void ThickSprings::set_springs(const unsigned* springs, int spring_count) {
  springs_.assign(springs, springs + 2 * spring_count);
  corners_.assign(floats_per_spring * spring_count, 0.0f);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  glBufferData(GL_ARRAY_BUFFER, sizeof(float) * corners_.size(), nullptr, GL_STREAM_DRAW);
  // Two triangles a spring, over its corners 4e .. 4e + 3.
  std::vector<unsigned> triangles(6 * spring_count);
  for (unsigned e = 0; e < static_cast<unsigned>(spring_count); ++e) {
    const unsigned quad[6] = {4 * e, 4 * e + 1, 4 * e + 2, 4 * e + 2, 4 * e + 1, 4 * e + 3};
    std::copy(quad, quad + 6, triangles.begin() + 6 * e);
  }
  glBindVertexArray(array_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof(unsigned) * triangles.size(), triangles.data(),
               GL_STATIC_DRAW);
  glBindVertexArray(0);
}

void ThickSprings::update(const float* positions, const float* colors,
                          const Eigen::Vector3f& color) {
  const int count = static_cast<int>(springs_.size() / 2);
  if (count == 0) return;
  for (int e = 0; e < count; ++e) {
    float* row = corners_.data() + floats_per_spring * e;
    for (int k = 0; k < 3; ++k) {
      row[k] = positions[3 * springs_[2 * e] + k];
      row[3 + k] = positions[3 * springs_[2 * e + 1] + k];
      row[6 + k] = colors != nullptr ? colors[3 * e + k] : color(k);
    }
    for (int corner = 1; corner < 4; ++corner)
      std::copy(row, row + floats_per_corner, row + corner * floats_per_corner);
  }
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof(float) * corners_.size(), corners_.data());
}

void ThickSprings::draw(const Eigen::Matrix4f& view_projection, int viewport_width,
                        int viewport_height, float width) const {
  const int count = static_cast<int>(springs_.size() / 2);
  if (count == 0) return;
  program_.use();
  glUniformMatrix4fv(program_.uniform("view_projection"), 1, GL_FALSE, view_projection.data());
  glUniform2f(program_.uniform("viewport_size"), static_cast<float>(viewport_width),
              static_cast<float>(viewport_height));
  glUniform1f(program_.uniform("width"), width);
  glBindVertexArray(array_);
  glDrawElements(GL_TRIANGLES, 6 * count, GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
}

}  // namespace wobble

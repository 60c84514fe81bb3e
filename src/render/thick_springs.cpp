#include "thick_springs.h"

namespace wobble {

namespace {

constexpr GLuint from_location = 0, to_location = 1, color_location = 2;
constexpr int floats_per_spring = 9;

}  // namespace

ThickSprings::ThickSprings() {
  glGenVertexArrays(1, &array_);
  glGenBuffers(1, &buffer_);
  glBindVertexArray(array_);
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  const GLsizei stride = floats_per_spring * sizeof(float);
  const GLuint locations[3] = {from_location, to_location, color_location};
  for (int k = 0; k < 3; ++k) {
    glEnableVertexAttribArray(locations[k]);
    glVertexAttribPointer(locations[k], 3, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(3 * k * sizeof(float)));
    glVertexAttribDivisor(locations[k], 1);  // one spring per instance, not per vertex
  }
  glBindVertexArray(0);
}

ThickSprings::~ThickSprings() {
  glDeleteBuffers(1, &buffer_);
  glDeleteVertexArrays(1, &array_);
}

void ThickSprings::set_springs(const unsigned* springs, int spring_count) {
  springs_.assign(springs, springs + 2 * spring_count);
  instances_.assign(floats_per_spring * spring_count, 0.0f);
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  glBufferData(GL_ARRAY_BUFFER, sizeof(float) * instances_.size(), nullptr, GL_STREAM_DRAW);
}

void ThickSprings::update(const float* positions, const float* colors,
                          const Eigen::Vector3f& color) {
  const int count = static_cast<int>(springs_.size() / 2);
  if (count == 0) return;
  for (int e = 0; e < count; ++e) {
    float* row = instances_.data() + floats_per_spring * e;
    for (int k = 0; k < 3; ++k) {
      row[k] = positions[3 * springs_[2 * e] + k];
      row[3 + k] = positions[3 * springs_[2 * e + 1] + k];
      row[6 + k] = colors != nullptr ? colors[3 * e + k] : color(k);
    }
  }
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof(float) * instances_.size(), instances_.data());
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
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count);
  glBindVertexArray(0);
}

}  // namespace wobble

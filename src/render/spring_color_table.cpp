#include "spring_color_table.h"

namespace wobble {

// WebGL 2 has no buffer textures: there GL_TEXTURE_BUFFER is an unknown target, and every call
// with it an INVALID_ENUM on the page's console (five a frame with the springs coloured). The
// page's shader draws the springs in one colour (shaders/es/spring_colors.frag), so the table
// holds nothing there.
#ifdef __EMSCRIPTEN__
constexpr bool buffer_textures = false;
#else
constexpr bool buffer_textures = true;
#endif

SpringColorTable::SpringColorTable() {
  if (!buffer_textures) return;
  glGenBuffers(1, &buffer_);
  glGenTextures(1, &texture_);
}

SpringColorTable::~SpringColorTable() {
  if (!buffer_textures) return;
  glDeleteTextures(1, &texture_);
  glDeleteBuffers(1, &buffer_);
}

void SpringColorTable::upload(const float* rgb, int spring_count) {
  if (!buffer_textures) return;
  const GLsizeiptr bytes = 3 * sizeof(float) * static_cast<GLsizeiptr>(spring_count);
  glBindBuffer(GL_TEXTURE_BUFFER, buffer_);
  if (spring_count != capacity_) {
    // The texture's view of the buffer is set again whenever its storage is replaced.
    glBufferData(GL_TEXTURE_BUFFER, bytes, rgb, GL_STREAM_DRAW);
    glBindTexture(GL_TEXTURE_BUFFER, texture_);
    glTexBuffer(GL_TEXTURE_BUFFER, GL_R32F, buffer_);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    capacity_ = spring_count;
  } else {
    glBufferSubData(GL_TEXTURE_BUFFER, 0, bytes, rgb);
  }
  glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

void SpringColorTable::bind(int unit) const {
  if (!buffer_textures) return;
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_BUFFER, texture_);
}

void SpringColorTable::unbind(int unit) const {
  if (!buffer_textures) return;
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_BUFFER, 0);
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace wobble

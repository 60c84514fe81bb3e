#ifndef WOBBLE_RENDER_SPRING_COLOR_TABLE_H
#define WOBBLE_RENDER_SPRING_COLOR_TABLE_H

#include <glad/gl.h>

namespace wobble {

// One colour per spring, as a buffer texture of #E × 3 floats (GL_R32F, one channel a texel, since
// GL 3.3 has no three-channel buffer format). The springs are drawn as one GL_LINES call over the
// spring index buffer, so a fragment's gl_PrimitiveID is its spring's row: each line gets its own
// colour while the springs keep sharing the vertex positions, with no per-spring copy of them.
// Needs a current GL context for its whole life. In the page (WebGL 2, no buffer textures) it
// makes no GL call at all.
class SpringColorTable {
 public:
  SpringColorTable();
  ~SpringColorTable();
  SpringColorTable(const SpringColorTable&) = delete;
  SpringColorTable& operator=(const SpringColorTable&) = delete;

  // Replace the colours: `rgb` is spring_count by 3 linear RGB, row-major.
  void upload(const float* rgb, int spring_count);
  // Bind the table to texture unit `unit` (for a samplerBuffer uniform set to that unit).
  void bind(int unit) const;
  void unbind(int unit) const;

 private:
  GLuint buffer_ = 0, texture_ = 0;
  int capacity_ = 0;  // springs the buffer has room for
};

}  // namespace wobble

#endif

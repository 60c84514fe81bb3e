#ifndef WOBBLE_RENDER_THICK_SPRINGS_H
#define WOBBLE_RENDER_THICK_SPRINGS_H

#include <glad/gl.h>

#include <Eigen/Core>
#include <vector>

#include "shader_program.h"

namespace wobble {

// Springs drawn as bands several pixels wide: the body of a mesh without faces (a rope, a net),
// which one-pixel lines in a colour near the ground grid's leave invisible on a projector. GL 3.3
// core and WebGL 2 draw no line wider than a pixel, so each spring is four corners, two
// triangles, that thick_spring.vert turns into a quad facing the camera, `width` pixels across,
// its ends squared off half a width past the vertices so that bends show no notch. Every corner
// carries the spring's two ends and its colour, gathered on the CPU, so each spring has its own
// colour in the browser too (which has no gl_PrimitiveID). Plain draws: the browser's GL loader
// offers no instanced ones. Needs a current GL context for its whole life.
class ThickSprings {
 public:
  ThickSprings();
  ~ThickSprings();
  ThickSprings(const ThickSprings&) = delete;
  ThickSprings& operator=(const ThickSprings&) = delete;

  // The springs: #E by 2 vertex indices, copied.
  void set_springs(const unsigned* springs, int spring_count);
  // This frame's ends: `positions` #V by 3 (m); `colors` #E by 3 linear RGB, or null for
  // `color` on every spring.
  void update(const float* positions, const float* colors, const Eigen::Vector3f& color);
  // Draw with the depth test on, into a viewport of `viewport_width` × `viewport_height` pixels.
  void draw(const Eigen::Matrix4f& view_projection, int viewport_width, int viewport_height,
            float width) const;

 private:
  ShaderProgram program_{"thick_spring.vert", "thick_spring.frag"};
  GLuint array_ = 0, buffer_ = 0, indices_ = 0;
  std::vector<unsigned> springs_;
  std::vector<float> corners_;  // #E × 4 by 9: from, to, colour
};

}  // namespace wobble

#endif

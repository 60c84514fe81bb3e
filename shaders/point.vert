#version 330 core
// Vertex markers. mark: 0 free, 1 pinned, 2 highlighted (under the mouse or held).
layout(location = 0) in vec3 position;
layout(location = 2) in float mark;

uniform mat4 view_projection;
uniform bool show_free_vertices;
uniform float pixel_ratio;

out float point_mark;

void main() {
  point_mark = mark;
  gl_Position = view_projection * vec4(position, 1.0);
  // Markers sit on the surface; pull them a little towards the eye so the surface never hides
  // the half of them that lies behind it.
  gl_Position.z -= 0.002 * gl_Position.w;
  if (mark < 0.5 && !show_free_vertices) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: the point is dropped
  }
  gl_PointSize = pixel_ratio * (mark > 1.5 ? 15.0 : (mark > 0.5 ? 10.0 : 3.0));
}

#version 330 core
// Vertex markers. mark: 0 free, 1 pinned, 2 highlighted (under the mouse or held).
layout(location = 0) in vec3 position;
layout(location = 2) in float mark;
layout(location = 5) in float pin_diameter;  // pixels: a pin's, from its spacing on screen

uniform mat4 view_projection;
uniform bool show_free_vertices;
uniform float pixel_ratio;
uniform vec3 eye;               // world position of the camera (m)
uniform float metres_per_pixel;  // a framebuffer pixel's size 1 m from the eye (m)

out float point_mark;
out float rimmed;  // 1: a dark rim around the fill (a marker large enough to hold one)

void main() {
  point_mark = mark;
  gl_PointSize =
      mark > 1.5 ? 15.0 * pixel_ratio : (mark > 0.5 ? pin_diameter : 3.0 * pixel_ratio);
  // On a small marker the rim would leave no fill: dense pins' rims merged into a black bar.
  rimmed = mark > 0.5 && gl_PointSize >= 6.0 * pixel_ratio ? 1.0 : 0.0;
  // A marker is a flat disc facing the eye, on a surface that slopes away under it. Pulled
  // towards the eye along its own ray (so it stays where it was on screen) by its diameter as a
  // world length, it stays whole on a surface turned up to 63 degrees from facing the eye, yet a
  // pin on the far side of a shape, a shape's thickness behind its front, stays hidden. A pull
  // by a fixed share of the depth range instead let pins tens of centimetres behind show through,
  // half hidden at the shape's silhouette as black specks. A pull growing with the surface's tilt
  // (from the vertex normal) kept edge-on pins whole, but in small images, where a disc is
  // centimetres wide, it let the second row of a jelly's pins show through again.
  vec3 to_eye = eye - position;
  float eye_distance = max(length(to_eye), 1e-6);
  float pull = min(gl_PointSize * metres_per_pixel * eye_distance, 0.5 * eye_distance);
  gl_Position = view_projection * vec4(position + to_eye * (pull / eye_distance), 1.0);
  if (mark < 0.5 && !show_free_vertices) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: the point is dropped
  }
}

#version 330 core
// A spring as a band `width` pixels wide (render/thick_springs.h): four corners a spring, each
// with both its ends, numbered in gl_VertexID % 4: 0 and 1 at its first end, 2 and 3 at its
// second, even on the right of its direction on screen and odd on the left.
layout(location = 0) in vec3 from_position;
layout(location = 1) in vec3 to_position;
layout(location = 2) in vec3 spring_color;

uniform mat4 view_projection;
uniform vec2 viewport_size;  // pixels
uniform float width;         // pixels

out vec3 band_color;
out float across;  // -1 on one edge of the band, 1 on the other

void main() {
  vec4 a = view_projection * vec4(from_position, 1.0);
  vec4 b = view_projection * vec4(to_position, 1.0);
  // An end behind the eye has no place on screen: the band stops just in front of it.
  const float nearest_w = 1e-4;
  if (a.w < nearest_w) a = mix(a, b, (nearest_w - a.w) / (b.w - a.w));
  if (b.w < nearest_w) b = mix(b, a, (nearest_w - b.w) / (a.w - b.w));
  vec2 half_viewport = 0.5 * viewport_size;
  vec2 along = b.xy / b.w * half_viewport - a.xy / a.w * half_viewport;
  float length_on_screen = length(along);
  along = length_on_screen > 1e-4 ? along / length_on_screen : vec2(1.0, 0.0);
  vec2 normal = vec2(-along.y, along.x);
  int corner = gl_VertexID % 4;
  bool second_end = corner >= 2;
  across = (corner % 2 == 0) ? -1.0 : 1.0;
  vec4 end = second_end ? b : a;
  vec2 offset = 0.5 * width * (across * normal + (second_end ? along : -along));
  gl_Position = vec4(end.xy + offset / half_viewport * end.w, end.zw);
  band_color = spring_color;
}

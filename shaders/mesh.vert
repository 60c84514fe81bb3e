#version 330 core
// Surface of the shape: positions and smooth normals, both updated every frame.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 3) in vec2 uv;
layout(location = 4) in vec3 color;  // by a quantity (strain, speed), when use_vertex_colors

uniform mat4 view_projection;
uniform vec3 eye;         // world position of the camera (m)
uniform float push_back;  // drawn this far further along the eye's ray (m), for the depth test only

out vec3 world_position;
out vec3 world_normal;
out vec2 texture_uv;
out vec3 vertex_color;

void main() {
  world_position = position;
  world_normal = normal;
  vertex_color = color;
  // OBJ's v grows upwards; image rows (as uploaded) grow downwards.
  texture_uv = vec2(uv.x, 1.0 - uv.y);
  // Along its own ray a point stays where it is on screen: only its depth moves.
  vec3 from_eye = position - eye;
  float eye_distance = length(from_eye);
  vec3 shown = eye_distance > 0.0 ? position + from_eye * (push_back / eye_distance) : position;
  gl_Position = view_projection * vec4(shown, 1.0);
}

#version 330 core
// Wireframe, springs and the ground grid: plain lines in one colour.
layout(location = 0) in vec3 position;

uniform mat4 view_projection;

void main() {
  gl_Position = view_projection * vec4(position, 1.0);
}

#version 330 core
// Wireframe, springs and the ground grid: plain lines in one colour.
layout(location = 0) in vec3 position;

uniform mat4 view_projection;
uniform vec3 eye;         // world position of the camera (m)
uniform float push_back;  // drawn this far further along the eye's ray (m), for the depth test only

void main() {
  // Along its own ray a point stays where it is on screen: only its depth moves.
  vec3 from_eye = position - eye;
  float eye_distance = length(from_eye);
  vec3 shown = eye_distance > 0.0 ? position + from_eye * (push_back / eye_distance) : position;
  gl_Position = view_projection * vec4(shown, 1.0);
}

#version 330 core
// A vertical gradient: lighter above the horizon, darker below.
in float height;

uniform vec3 top_color;
uniform vec3 bottom_color;

out vec4 color;

void main() {
  color = vec4(mix(bottom_color, top_color, clamp(height, 0.0, 1.0)), 1.0);
}

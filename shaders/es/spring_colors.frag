#version 300 es
// The browser's (WebGL 2, GLSL ES 3.00) variant of spring_colors.frag. GLSL ES has neither
// buffer textures nor gl_PrimitiveID, so the springs cannot look up their own colours: they are
// drawn in one neutral colour, and the surface still shows the quantity per vertex.
precision highp float;

uniform float alpha;

out vec4 color;

void main() {
  color = vec4(0.85, 0.85, 0.85, alpha);
}

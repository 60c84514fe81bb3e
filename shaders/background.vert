#version 330 core
// One triangle covering the viewport, with no vertex buffer.
out float height;

void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  height = corner.y;
  gl_Position = vec4(2.0 * corner - 1.0, 0.0, 1.0);
}

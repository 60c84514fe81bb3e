#version 330 core
// Dear ImGui's triangles (the panel, its windows, the legend): 2-D positions in the display's
// pixels, turned into clip space by `projection`; a texture coordinate into the font atlas and
// a colour per vertex (four bytes, normalized).
layout(location = 0) in vec2 position;
layout(location = 1) in vec2 uv;
layout(location = 2) in vec4 color;

uniform mat4 projection;

out vec2 atlas_uv;
out vec4 vertex_color;

void main() {
  atlas_uv = uv;
  vertex_color = color;
  gl_Position = projection * vec4(position, 0.0, 1.0);
}

#version 330 core
// The vertex colour times the atlas (white where a shape has no glyph), blended over the scene.
in vec2 atlas_uv;
in vec4 vertex_color;

uniform sampler2D atlas;

out vec4 fragment;

void main() {
  fragment = vertex_color * texture(atlas, atlas_uv);
}

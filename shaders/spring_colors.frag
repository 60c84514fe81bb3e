#version 330 core
// Springs coloured one by one (by strain or speed). They are drawn as one GL_LINES call over the
// spring index buffer, so the primitive number is the spring's row of the colour table: #E × 3
// floats in a buffer texture, one channel per texel.
uniform samplerBuffer spring_colors;
uniform float alpha;

out vec4 color;

void main() {
  int row = 3 * gl_PrimitiveID;
  color = vec4(texelFetch(spring_colors, row).r, texelFetch(spring_colors, row + 1).r,
               texelFetch(spring_colors, row + 2).r, alpha);
}

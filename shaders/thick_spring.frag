#version 330 core
// Shaded across its width like a lit cord: full colour along the middle, darker at the edges, so
// the band keeps an outline against a background or ground of its own brightness.
in vec3 band_color;
in float across;

out vec4 color;

void main() {
  float roundness = sqrt(max(1.0 - across * across, 0.0));
  color = vec4(band_color * (0.45 + 0.6 * roundness), 1.0);
}

#version 330 core
// Two-sided lighting: a back face turns its normal around and takes its own colour, so cloth seen
// from behind is lit like the front and still tells the two sides apart.
in vec3 world_position;
in vec3 world_normal;
in vec2 texture_uv;
in vec3 vertex_color;

uniform vec3 eye;
uniform vec3 front_color;
uniform vec3 back_color;
uniform bool use_texture;
uniform bool use_vertex_colors;  // coloured by a quantity: both sides alike, no texture
uniform sampler2D surface_texture;

out vec4 color;

void main() {
  vec3 n = normalize(world_normal);
  vec3 base = front_color;
  if (use_texture) base = texture(surface_texture, texture_uv).rgb;
  if (use_vertex_colors) base = vertex_color;
  if (!gl_FrontFacing) {
    n = -n;
    // A textured back shows the texture through, a little darker, as printed fabric does. A
    // quantity reads the same from either side.
    if (!use_vertex_colors) base = use_texture ? 0.8 * base : back_color;
  }
  vec3 to_eye = normalize(eye - world_position);
  // A key light just above the viewer keeps the lit side facing the camera while orbiting. It
  // wraps a little past 90°, so folds turning away from it darken gradually instead of going flat.
  vec3 light = normalize(to_eye + vec3(0.0, 0.5, 0.0));
  float diffuse = max(0.75 * dot(n, light) + 0.25, 0.0);
  float specular = pow(max(dot(n, normalize(light + to_eye)), 0.0), 48.0);
  // Sky above, ground bounce below.
  vec3 ambient = mix(vec3(0.26, 0.24, 0.22), vec3(0.40, 0.44, 0.50), 0.5 + 0.5 * n.y);
  color = vec4(base * (ambient + 0.7 * diffuse) + vec3(0.15 * specular), 1.0);
}

#version 330 core
in float point_mark;
in float rimmed;

out vec4 color;

void main() {
  vec2 offset = 2.0 * gl_PointCoord - 1.0;
  float radius2 = dot(offset, offset);
  if (radius2 > 1.0) discard;
  vec3 fill = point_mark > 1.5 ? vec3(1.0, 0.86, 0.2)
                               : (point_mark > 0.5 ? vec3(0.92, 0.16, 0.22) : vec3(0.92));
  // A dark rim keeps pins readable on any surface colour. Pins too dense for one (small
  // markers, sized by their spacing) are lightened instead: a light line of dots.
  bool rim = rimmed > 0.5 && radius2 > 0.5;
  if (point_mark > 0.5 && point_mark < 1.5 && rimmed < 0.5) fill = mix(fill, vec3(1.0), 0.45);
  color = vec4(rim ? vec3(0.06) : fill, 1.0);
}

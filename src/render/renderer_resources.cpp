#include "renderer_resources.h"

namespace wobble {

namespace {

constexpr GLuint position_location = 0, normal_location = 1, mark_location = 2, uv_location = 3,
                 color_location = 4, pin_diameter_location = 5;

void attribute(GLuint buffer, GLuint location, int size, GLenum type) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, size, type, GL_FALSE, 0, nullptr);
}

}  // namespace

Renderer::Resources::Resources() {
  GLuint buffers[12];
  glGenBuffers(12, buffers);
  positions = buffers[0];
  normals = buffers[1];
  marks = buffers[2];
  triangle_indices = buffers[3];
  spring_indices = buffers[4];
  grid_vertices = buffers[5];
  uvs = buffers[6];
  solid_positions = buffers[7];
  solid_normals = buffers[8];
  solid_indices = buffers[9];
  vertex_colors = buffers[10];
  pin_diameters = buffers[11];
  glGenTextures(1, &texture);
  GLuint arrays[6];
  glGenVertexArrays(6, arrays);
  surface_array = arrays[0];
  spring_array = arrays[1];
  point_array = arrays[2];
  grid_array = arrays[3];
  empty_array = arrays[4];
  solid_array = arrays[5];

  glBindVertexArray(surface_array);
  attribute(positions, position_location, 3, GL_FLOAT);
  attribute(normals, normal_location, 3, GL_FLOAT);
  attribute(uvs, uv_location, 2, GL_FLOAT);
  attribute(vertex_colors, color_location, 3, GL_FLOAT);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, triangle_indices);

  glBindVertexArray(spring_array);
  attribute(positions, position_location, 3, GL_FLOAT);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, spring_indices);

  glBindVertexArray(point_array);
  attribute(positions, position_location, 3, GL_FLOAT);
  attribute(marks, mark_location, 1, GL_UNSIGNED_BYTE);
  attribute(pin_diameters, pin_diameter_location, 1, GL_FLOAT);

  glBindVertexArray(grid_array);
  attribute(grid_vertices, position_location, 3, GL_FLOAT);

  glBindVertexArray(solid_array);
  attribute(solid_positions, position_location, 3, GL_FLOAT);
  attribute(solid_normals, normal_location, 3, GL_FLOAT);
  // The surface's program reads uv; the solids have none, so the attribute is a constant.
  glDisableVertexAttribArray(uv_location);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, solid_indices);
  glBindVertexArray(0);
}

Renderer::Resources::~Resources() {
  const GLuint buffers[12] = {positions,      normals,       marks,         triangle_indices,
                              spring_indices, grid_vertices, uvs,           solid_positions,
                              solid_normals,  solid_indices, vertex_colors, pin_diameters};
  glDeleteBuffers(12, buffers);
  glDeleteTextures(1, &texture);
  const GLuint arrays[6] = {surface_array, spring_array, point_array,
                            grid_array,    empty_array,  solid_array};
  glDeleteVertexArrays(6, arrays);
}

}  // namespace wobble

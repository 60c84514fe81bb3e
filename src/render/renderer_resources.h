#ifndef WOBBLE_RENDER_RENDERER_RESOURCES_H
#define WOBBLE_RENDER_RENDERER_RESOURCES_H

// The GL objects a Renderer owns (renderer.cpp's own header, not for other rooms): its programs,
// buffers, vertex arrays and texture, made and laid out in renderer_resources.cpp, and what the
// last set_* and update() calls left for draw().
#include <glad/gl.h>

#include <vector>

#include "pin_mark_sizes.h"
#include "renderer.h"
#include "shader_program.h"
#include "spring_color_table.h"
#include "thick_springs.h"

namespace wobble {

struct Renderer::Resources {
  ShaderProgram mesh{"mesh.vert", "mesh.frag"};
  ShaderProgram line{"line.vert", "line.frag"};
  ShaderProgram point{"point.vert", "point.frag"};
  ShaderProgram background{"background.vert", "background.frag"};
  ShaderProgram colored_springs{"line.vert", "spring_colors.frag"};

  // One position buffer feeds three vertex arrays, each with its own element buffer: the surface
  // (with normals), the springs, and the markers (with marks).
  GLuint positions = 0, normals = 0, marks = 0, triangle_indices = 0, spring_indices = 0, uvs = 0;
  GLuint texture = 0;
  bool textured = false, has_uv = false;
  GLuint surface_array = 0, spring_array = 0, point_array = 0;
  GLuint grid_array = 0, grid_vertices = 0, empty_array = 0;
  // The solids have buffers of their own, drawn through the surface's program.
  GLuint solid_array = 0, solid_positions = 0, solid_normals = 0, solid_indices = 0;
  // Colours by a quantity, used while the last update() had them.
  GLuint vertex_colors = 0;
  // Each pin marker's diameter (pixels), from its spacing on screen; #V, read for pins only.
  GLuint pin_diameters = 0;
  PinMarks pin_marks;
  SpringColorTable spring_colors;
  // The springs of a mesh without faces, drawn thick in the surface's colour.
  ThickSprings thick_springs;
  bool vertex_colored = false, springs_colored = false;
  // Desktop GL sizes points from the shader only with GL_PROGRAM_POINT_SIZE on; GL ES (WebGL 2)
  // always does, and refuses the enum (a console warning twice a frame in the page).
  bool program_point_size = false;
  int vertex_count = 0, triangle_count = 0, spring_count = 0, grid_vertex_count = 0;
  int solid_triangle_count = 0;
  // The surface's longest triangle edge this frame (m): how deep its triangles can cut into a
  // collider whose contact holds only the vertices out.
  float longest_triangle_edge = 0.0f;
  std::vector<unsigned> triangles;  // #F by 3, a copy for measuring the edges
  SurfaceColors colors;

  // Makes the buffers, texture and vertex arrays and binds each array's attributes.
  Resources();
  ~Resources();
  Resources(const Resources&) = delete;
  Resources& operator=(const Resources&) = delete;
};

}  // namespace wobble

#endif

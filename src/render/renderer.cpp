#include "renderer.h"

#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "renderer_resources.h"

namespace wobble {

namespace {

constexpr int spring_color_unit = 1;  // the surface's texture has unit 0
// A mesh without faces is its springs: bands this many pixels wide (times the pixel ratio) read
// from the back of a classroom.
constexpr float thick_spring_width = 6.0f;

// The longest edge of the triangles (m); positions #V by 3, triangles #F by 3.
float longest_edge(const float* positions, const std::vector<unsigned>& triangles) {
  float longest_squared = 0.0f;
  for (std::size_t t = 0; t < triangles.size(); t += 3) {
    for (int k = 0; k < 3; ++k) {
      const float* a = positions + 3 * triangles[t + k];
      const float* b = positions + 3 * triangles[t + (k + 1) % 3];
      const float dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
      longest_squared = std::max(longest_squared, dx * dx + dy * dy + dz * dz);
    }
  }
  return std::sqrt(longest_squared);
}

}  // namespace

Renderer::Renderer() : resources_(std::make_unique<Resources>()) {
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  resources_->program_point_size =
      version == nullptr || std::string(version).rfind("OpenGL ES", 0) != 0;
  set_ground(GroundGrid());
}

Renderer::~Renderer() = default;

void Renderer::set_topology(const MeshTopology& topology) {
  Resources& r = *resources_;
  r.vertex_count = topology.vertex_count;
  r.triangle_count = topology.triangle_count;
  r.spring_count = topology.spring_count;
  glBindVertexArray(0);  // element buffers are vertex-array state: change none by accident
  glBindBuffer(GL_ARRAY_BUFFER, r.positions);
  glBufferData(GL_ARRAY_BUFFER, 3 * sizeof(float) * r.vertex_count, nullptr, GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, r.normals);
  glBufferData(GL_ARRAY_BUFFER, 3 * sizeof(float) * r.vertex_count, nullptr, GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, r.marks);
  glBufferData(GL_ARRAY_BUFFER, r.vertex_count, nullptr, GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, r.vertex_colors);
  glBufferData(GL_ARRAY_BUFFER, 3 * sizeof(float) * r.vertex_count, nullptr, GL_STREAM_DRAW);
  r.pin_marks.reset(r.vertex_count);
  glBindBuffer(GL_ARRAY_BUFFER, r.pin_diameters);
  glBufferData(GL_ARRAY_BUFFER, sizeof(float) * r.vertex_count, r.pin_marks.diameters().data(),
               GL_STREAM_DRAW);
  r.vertex_colored = r.springs_colored = false;
  // Without uv the buffer still holds zeros, so the attribute never reads past its end.
  r.has_uv = topology.uv != nullptr;
  const std::vector<float> no_uv(r.has_uv ? 0 : 2 * r.vertex_count, 0.0f);
  glBindBuffer(GL_ARRAY_BUFFER, r.uvs);
  glBufferData(GL_ARRAY_BUFFER, 2 * sizeof(float) * r.vertex_count,
               r.has_uv ? topology.uv : no_uv.data(), GL_STATIC_DRAW);
  glBindVertexArray(r.surface_array);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, 3 * sizeof(unsigned) * r.triangle_count, topology.triangles,
               GL_STATIC_DRAW);
  r.triangles.assign(topology.triangles, topology.triangles + 3 * r.triangle_count);
  glBindVertexArray(r.spring_array);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, 2 * sizeof(unsigned) * r.spring_count, topology.springs,
               GL_STATIC_DRAW);
  glBindVertexArray(0);
  r.thick_springs.set_springs(topology.springs, r.triangle_count == 0 ? r.spring_count : 0);
}

void Renderer::set_ground(const GroundGrid& ground) {
  std::vector<float> vertices;
  const int lines_per_side = static_cast<int>(ground.half_extent / ground.spacing + 0.5f);
  const float extent = lines_per_side * ground.spacing;
  for (int i = -lines_per_side; i <= lines_per_side; ++i) {
    const float offset = i * ground.spacing;
    const float segments[12] = {
        ground.center_x + offset, ground.height, ground.center_z - extent,
        ground.center_x + offset, ground.height, ground.center_z + extent,
        ground.center_x - extent, ground.height, ground.center_z + offset,
        ground.center_x + extent, ground.height, ground.center_z + offset,
    };
    vertices.insert(vertices.end(), segments, segments + 12);
  }
  Resources& r = *resources_;
  r.grid_vertex_count = static_cast<int>(vertices.size() / 3);
  glBindBuffer(GL_ARRAY_BUFFER, r.grid_vertices);
  glBufferData(GL_ARRAY_BUFFER, sizeof(float) * vertices.size(), vertices.data(), GL_STATIC_DRAW);
}

void Renderer::set_colors(const SurfaceColors& colors) {
  resources_->colors = colors;
}

void Renderer::set_texture(const TextureImage& image) {
  Resources& r = *resources_;
  r.textured = image.rgba != nullptr && image.width > 0 && image.height > 0;
  if (!r.textured) return;
  glBindTexture(GL_TEXTURE_2D, r.texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               image.rgba);
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glBindTexture(GL_TEXTURE_2D, 0);
}

void Renderer::set_solids(const SolidMesh& solids) {
  Resources& r = *resources_;
  r.solid_triangle_count = solids.vertex_count > 0 ? solids.triangle_count : 0;
  if (r.solid_triangle_count == 0) return;
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, r.solid_positions);
  glBufferData(GL_ARRAY_BUFFER, 3 * sizeof(float) * solids.vertex_count, solids.positions,
               GL_DYNAMIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, r.solid_normals);
  glBufferData(GL_ARRAY_BUFFER, 3 * sizeof(float) * solids.vertex_count, solids.normals,
               GL_DYNAMIC_DRAW);
  glBindVertexArray(r.solid_array);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, 3 * sizeof(unsigned) * r.solid_triangle_count,
               solids.triangles, GL_DYNAMIC_DRAW);
  glBindVertexArray(0);
}

void Renderer::update(const MeshFrame& frame) {
  Resources& r = *resources_;
  glBindBuffer(GL_ARRAY_BUFFER, r.positions);
  glBufferSubData(GL_ARRAY_BUFFER, 0, 3 * sizeof(float) * r.vertex_count, frame.positions);
  glBindBuffer(GL_ARRAY_BUFFER, r.normals);
  glBufferSubData(GL_ARRAY_BUFFER, 0, 3 * sizeof(float) * r.vertex_count, frame.normals);
  glBindBuffer(GL_ARRAY_BUFFER, r.marks);
  glBufferSubData(GL_ARRAY_BUFFER, 0, r.vertex_count, frame.marks);
  r.longest_triangle_edge = longest_edge(frame.positions, r.triangles);
  // The pins' places, for sizing their markers by their spacing on screen in draw().
  r.pin_marks.take(frame.marks, frame.positions);
  // Colours cost an upload only while they are shown.
  r.vertex_colored = frame.vertex_colors != nullptr;
  if (r.vertex_colored) {
    glBindBuffer(GL_ARRAY_BUFFER, r.vertex_colors);
    glBufferSubData(GL_ARRAY_BUFFER, 0, 3 * sizeof(float) * r.vertex_count, frame.vertex_colors);
  }
  r.springs_colored = frame.spring_colors != nullptr && r.spring_count > 0;
  if (r.triangle_count == 0) {
    r.thick_springs.update(frame.positions, frame.spring_colors, r.colors.front);
  } else if (r.springs_colored) {
    r.spring_colors.upload(frame.spring_colors, r.spring_count);
  }
}

void Renderer::size_pin_marks(const Eigen::Matrix4f& view_projection, int width, int height,
                              float pixel_ratio) {
  Resources& r = *resources_;
  if (r.pin_marks.empty()) return;
  const std::vector<float>& diameters =
      r.pin_marks.size(view_projection, width, height, pixel_ratio);
  glBindBuffer(GL_ARRAY_BUFFER, r.pin_diameters);
  glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof(float) * r.vertex_count, diameters.data());
}

void Renderer::draw(const Eigen::Matrix4f& view, const Eigen::Matrix4f& projection,
                    const Eigen::Vector3f& eye, const ViewLayers& layers, int width, int height,
                    float pixel_ratio, int x, int y) {
  const Resources& r = *resources_;
  const Eigen::Matrix4f view_projection = projection * view;
  glViewport(x, y, width, height);
  glDisable(GL_CULL_FACE);  // both sides of a cloth are visible
  glDisable(GL_BLEND);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  // glClear ignores the viewport: the scissor keeps it to this one.
  glEnable(GL_SCISSOR_TEST);
  glScissor(x, y, width, height);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);

  glDisable(GL_DEPTH_TEST);
  r.background.use();
  glUniform3f(r.background.uniform("top_color"), 0.33f, 0.36f, 0.41f);
  glUniform3f(r.background.uniform("bottom_color"), 0.11f, 0.12f, 0.14f);
  glBindVertexArray(r.empty_array);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);

  // The contact keeps the surface's vertices a contact offset (a few mm) outside a collider, but
  // its flat triangles cut straight across the collider's edges between them, deeper than the
  // offset (docs/viewer.md), and a table's edge showed through a tablecloth as a dashed line.
  // Half the longest triangle edge bounds that cut, so what the surface rests on, the solids and
  // the ground grid together, is drawn that far further along each eye ray: nothing moves on
  // screen, the surface in front of a solid wins the depth test whether it cuts the edge or not,
  // and the grid and the solids keep their order where they meet.
  const bool solids_shown = layers.solids && r.solid_triangle_count > 0;
  const float stage_push = solids_shown && layers.surface ? 0.5f * r.longest_triangle_edge : 0.0f;

  const auto lines = [&](const float rgba[4], float push_back) {
    r.line.use();
    glUniformMatrix4fv(r.line.uniform("view_projection"), 1, GL_FALSE, view_projection.data());
    glUniform4fv(r.line.uniform("line_color"), 1, rgba);
    glUniform3fv(r.line.uniform("eye"), 1, eye.data());
    glUniform1f(r.line.uniform("push_back"), push_back);
  };
  if (layers.ground) {
    const float grid_color[4] = {0.42f, 0.45f, 0.50f, 1.0f};
    lines(grid_color, stage_push);
    glBindVertexArray(r.grid_array);
    glDrawArrays(GL_LINES, 0, r.grid_vertex_count);
  }

  // Shaded triangles through the surface's program (two-sided lighting), pushed back in depth by
  // glPolygonOffset(factor, units) and by `push_back` metres along the eye's rays.
  const auto shaded = [&](const Eigen::Vector3f& front, const Eigen::Vector3f& back, bool textured,
                          bool vertex_colored, float factor, float units, float push_back,
                          GLuint array, int count) {
    r.mesh.use();
    glUniform1f(r.mesh.uniform("push_back"), push_back);
    glUniformMatrix4fv(r.mesh.uniform("view_projection"), 1, GL_FALSE, view_projection.data());
    glUniform3fv(r.mesh.uniform("eye"), 1, eye.data());
    glUniform3fv(r.mesh.uniform("front_color"), 1, front.data());
    glUniform3fv(r.mesh.uniform("back_color"), 1, back.data());
    glUniform1i(r.mesh.uniform("use_texture"), textured ? 1 : 0);
    glUniform1i(r.mesh.uniform("use_vertex_colors"), vertex_colored ? 1 : 0);
    glUniform1i(r.mesh.uniform("surface_texture"), 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, textured ? r.texture : 0);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(factor, units);
    glBindVertexArray(array);
    glDrawElements(GL_TRIANGLES, 3 * count, GL_UNSIGNED_INT, nullptr);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glBindTexture(GL_TEXTURE_2D, 0);
  };
  if (layers.surface && r.triangle_count > 0) {
    // Pushed back a little so edges drawn on it win the depth test.
    shaded(r.colors.front, r.colors.back, r.textured && r.has_uv && !r.vertex_colored,
           r.vertex_colored, 1.0f, 1.0f, 0.0f, r.surface_array, r.triangle_count);
  }
  if (solids_shown) {
    // Pushed back further than the surface, and by stage_push (above).
    shaded(r.colors.solid, r.colors.solid, false, false, 4.0f, 64.0f, stage_push, r.solid_array,
           r.solid_triangle_count);
  }
  // Edges and springs are blended, so the shading still shows through a dense mesh.
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  if (layers.wireframe && r.triangle_count > 0) {
    const float wire_color[4] = {0.05f, 0.05f, 0.07f, 0.6f};
    lines(wire_color, 0.0f);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glBindVertexArray(r.surface_array);
    glDrawElements(GL_TRIANGLES, 3 * r.triangle_count, GL_UNSIGNED_INT, nullptr);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  }
  if (layers.springs && r.spring_count > 0 && r.triangle_count == 0) {
    glDisable(GL_BLEND);  // opaque: the body of the shape, not lines over it
    r.thick_springs.draw(view_projection, width, height, thick_spring_width * pixel_ratio);
  } else if (layers.springs && r.spring_count > 0 && r.springs_colored) {
    // More opaque than plain springs, so that each line's colour reads.
    r.colored_springs.use();
    glUniformMatrix4fv(r.colored_springs.uniform("view_projection"), 1, GL_FALSE,
                       view_projection.data());
    glUniform1i(r.colored_springs.uniform("spring_colors"), spring_color_unit);
    glUniform1f(r.colored_springs.uniform("alpha"), 0.8f);
    r.spring_colors.bind(spring_color_unit);
    glBindVertexArray(r.spring_array);
    glDrawElements(GL_LINES, 2 * r.spring_count, GL_UNSIGNED_INT, nullptr);
    r.spring_colors.unbind(spring_color_unit);
  } else if (layers.springs && r.spring_count > 0) {
    const float spring_color[4] = {0.55f, 0.95f, 0.85f, 0.45f};
    lines(spring_color, 0.0f);
    glBindVertexArray(r.spring_array);
    glDrawElements(GL_LINES, 2 * r.spring_count, GL_UNSIGNED_INT, nullptr);
  }
  glDisable(GL_BLEND);

  if (r.vertex_count > 0) {
    size_pin_marks(view_projection, width, height, pixel_ratio);
    r.point.use();
    glUniformMatrix4fv(r.point.uniform("view_projection"), 1, GL_FALSE, view_projection.data());
    glUniform1i(r.point.uniform("show_free_vertices"), layers.points ? 1 : 0);
    glUniform1f(r.point.uniform("pixel_ratio"), pixel_ratio);
    glUniform3fv(r.point.uniform("eye"), 1, eye.data());
    // projection(1, 1) = 1 / tan(fov / 2): the viewport's height spans 2 tan(fov / 2) at 1 m.
    glUniform1f(r.point.uniform("metres_per_pixel"),
                2.0f / (projection(1, 1) * static_cast<float>(std::max(height, 1))));
    if (r.program_point_size) glEnable(GL_PROGRAM_POINT_SIZE);
    glBindVertexArray(r.point_array);
    glDrawArrays(GL_POINTS, 0, r.vertex_count);
    if (r.program_point_size) glDisable(GL_PROGRAM_POINT_SIZE);
  }
  glBindVertexArray(0);
  glUseProgram(0);
}

}  // namespace wobble

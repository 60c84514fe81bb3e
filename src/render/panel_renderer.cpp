#include "render/panel_renderer.h"

#include <imgui.h>

#include <cstddef>
#include <cstdint>

#include "render/shader_program.h"

namespace wobble {

namespace {

// What draw() changes, read before and put back after, so that the scene's renderer finds the
// state as it left it.
struct SavedState {
  GLint program = 0, texture = 0, active_texture = 0, vertex_array = 0, array_buffer = 0;
  GLint viewport[4] = {}, scissor_box[4] = {};
  GLint blend_rgb_source = 0, blend_rgb_destination = 0, blend_alpha_source = 0,
        blend_alpha_destination = 0, blend_rgb_equation = 0, blend_alpha_equation = 0;
  GLboolean blend = GL_FALSE, cull = GL_FALSE, depth = GL_FALSE, stencil = GL_FALSE,
            scissor = GL_FALSE;
#ifndef __EMSCRIPTEN__
  // WebGL 2 has neither polygon modes nor primitive restart as state: asking is an error there.
  GLint polygon_mode[2] = {};
  GLboolean primitive_restart = GL_FALSE;
#endif

  SavedState() {
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active_texture);
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertex_array);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &array_buffer);
    glGetIntegerv(GL_VIEWPORT, viewport);
    glGetIntegerv(GL_SCISSOR_BOX, scissor_box);
    glGetIntegerv(GL_BLEND_SRC_RGB, &blend_rgb_source);
    glGetIntegerv(GL_BLEND_DST_RGB, &blend_rgb_destination);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, &blend_alpha_source);
    glGetIntegerv(GL_BLEND_DST_ALPHA, &blend_alpha_destination);
    glGetIntegerv(GL_BLEND_EQUATION_RGB, &blend_rgb_equation);
    glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &blend_alpha_equation);
    blend = glIsEnabled(GL_BLEND);
    cull = glIsEnabled(GL_CULL_FACE);
    depth = glIsEnabled(GL_DEPTH_TEST);
    stencil = glIsEnabled(GL_STENCIL_TEST);
    scissor = glIsEnabled(GL_SCISSOR_TEST);
#ifndef __EMSCRIPTEN__
    glGetIntegerv(GL_POLYGON_MODE, polygon_mode);
    primitive_restart = glIsEnabled(GL_PRIMITIVE_RESTART);
#endif
  }

  static void set(GLenum capability, GLboolean on) {
    if (on) {
      glEnable(capability);
    } else {
      glDisable(capability);
    }
  }

  ~SavedState() {
    glUseProgram(static_cast<GLuint>(program));
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture));
    glActiveTexture(static_cast<GLenum>(active_texture));
    glBindVertexArray(static_cast<GLuint>(vertex_array));
    glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(array_buffer));
    glBlendEquationSeparate(static_cast<GLenum>(blend_rgb_equation),
                            static_cast<GLenum>(blend_alpha_equation));
    glBlendFuncSeparate(
        static_cast<GLenum>(blend_rgb_source), static_cast<GLenum>(blend_rgb_destination),
        static_cast<GLenum>(blend_alpha_source), static_cast<GLenum>(blend_alpha_destination));
    set(GL_BLEND, blend);
    set(GL_CULL_FACE, cull);
    set(GL_DEPTH_TEST, depth);
    set(GL_STENCIL_TEST, stencil);
    set(GL_SCISSOR_TEST, scissor);
#ifndef __EMSCRIPTEN__
    glPolygonMode(GL_FRONT_AND_BACK, static_cast<GLenum>(polygon_mode[0]));
    set(GL_PRIMITIVE_RESTART, primitive_restart);
#endif
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    glScissor(scissor_box[0], scissor_box[1], scissor_box[2], scissor_box[3]);
  }
  SavedState(const SavedState&) = delete;
  SavedState& operator=(const SavedState&) = delete;
};

// ImDrawVert's three attributes at `first_vertex` of the bound array buffer: where a command's
// indices count from (ImDrawCmd::VtxOffset). An offset in the pointers rather than
// glDrawElementsBaseVertex, which WebGL 2 lacks.
void point_attributes(std::size_t first_vertex) {
  const std::size_t base = first_vertex * sizeof(ImDrawVert);
  const auto at = [base](std::size_t member) {
    return reinterpret_cast<const void*>(static_cast<std::uintptr_t>(base + member));
  };
  const GLsizei stride = sizeof(ImDrawVert);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride, at(offsetof(ImDrawVert, pos)));
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, stride, at(offsetof(ImDrawVert, uv)));
  glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride, at(offsetof(ImDrawVert, col)));
}

}  // namespace

PanelRenderer::PanelRenderer()
    : program_(std::make_unique<ShaderProgram>("panel.vert", "panel.frag")) {
  projection_ = program_->uniform("projection");
  atlas_ = program_->uniform("atlas");
  glGenVertexArrays(1, &vertex_array_);
  glGenBuffers(1, &vertex_buffer_);
  glGenBuffers(1, &index_buffer_);
  GLint vertex_array = 0, array_buffer = 0;
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertex_array);
  glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &array_buffer);
  glBindVertexArray(vertex_array_);
  glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_);  // kept by the vertex array
  for (GLuint attribute = 0; attribute < 3; ++attribute)
    glEnableVertexAttribArray(attribute);
  point_attributes(0);
  glBindVertexArray(static_cast<GLuint>(vertex_array));
  glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(array_buffer));
  // Commands may start anywhere in a list's vertices, so lists of any length draw with 16-bit
  // indices.
  ImGui::GetIO().BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
  ImGui::GetIO().BackendRendererName = "wobble";
  ImGui::GetIO().BackendRendererUserData = this;
  upload_fonts();
}

PanelRenderer::~PanelRenderer() {
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->SetTexID(ImTextureID{});
  io.BackendRendererName = nullptr;
  if (io.BackendRendererUserData == this) io.BackendRendererUserData = nullptr;
  io.BackendFlags &= ~ImGuiBackendFlags_RendererHasVtxOffset;
  glDeleteTextures(1, &font_texture_);
  glDeleteBuffers(1, &index_buffer_);
  glDeleteBuffers(1, &vertex_buffer_);
  glDeleteVertexArrays(1, &vertex_array_);
}

void PanelRenderer::upload_fonts() {
  ImGuiIO& io = ImGui::GetIO();
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  GLint texture = 0, row_length = 0, alignment = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
  glGetIntegerv(GL_UNPACK_ROW_LENGTH, &row_length);
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
  if (font_texture_ == 0) glGenTextures(1, &font_texture_);
  glBindTexture(GL_TEXTURE_2D, font_texture_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, row_length);
  glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
  glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture));
  io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(font_texture_)));
}

void PanelRenderer::draw(const ImDrawData& data) {
  // The framebuffer's pixels: the display's size times its scale (a high-DPI screen's 2).
  const int width = static_cast<int>(data.DisplaySize.x * data.FramebufferScale.x);
  const int height = static_cast<int>(data.DisplaySize.y * data.FramebufferScale.y);
  if (width <= 0 || height <= 0 || data.CmdListsCount == 0) return;
  const SavedState saved;

  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  // Colour: over; alpha: what a later composite of the framebuffer would want.
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_SCISSOR_TEST);
#ifndef __EMSCRIPTEN__
  glDisable(GL_PRIMITIVE_RESTART);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
#endif
  glViewport(0, 0, width, height);

  // Display pixels (y down, origin at DisplayPos) to clip space: an orthographic projection,
  // column by column.
  const float left = data.DisplayPos.x, right = data.DisplayPos.x + data.DisplaySize.x;
  const float top = data.DisplayPos.y, bottom = data.DisplayPos.y + data.DisplaySize.y;
  const float projection[16] = {2.0f / (right - left),
                                0.0f,
                                0.0f,
                                0.0f,
                                0.0f,
                                2.0f / (top - bottom),
                                0.0f,
                                0.0f,
                                0.0f,
                                0.0f,
                                -1.0f,
                                0.0f,
                                (right + left) / (left - right),
                                (top + bottom) / (bottom - top),
                                0.0f,
                                1.0f};
  program_->use();
  glUniform1i(atlas_, 0);
  glUniformMatrix4fv(projection_, 1, GL_FALSE, projection);
  glBindVertexArray(vertex_array_);
  glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);

  const ImVec2 origin = data.DisplayPos, scale = data.FramebufferScale;
  const GLenum index_type = sizeof(ImDrawIdx) == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT;
  for (int list = 0; list < data.CmdListsCount; ++list) {
    const ImDrawList& commands = *data.CmdLists[list];
    glBufferData(GL_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(commands.VtxBuffer.Size) *
                     static_cast<GLsizeiptr>(sizeof(ImDrawVert)),
                 commands.VtxBuffer.Data, GL_STREAM_DRAW);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(commands.IdxBuffer.Size) *
                     static_cast<GLsizeiptr>(sizeof(ImDrawIdx)),
                 commands.IdxBuffer.Data, GL_STREAM_DRAW);
    std::size_t pointed = 0;
    point_attributes(pointed);
    for (const ImDrawCmd& command : commands.CmdBuffer) {
      if (command.UserCallback != nullptr) {
        // Wobble adds no callbacks of its own; ImGui's "reset the render state" needs nothing
        // here, as every command sets what it uses.
        if (command.UserCallback != ImDrawCallback_ResetRenderState)
          command.UserCallback(&commands, &command);
        continue;
      }
      // The clip rectangle in framebuffer pixels; GL's scissor counts rows from the bottom.
      const float clip_left = (command.ClipRect.x - origin.x) * scale.x;
      const float clip_top = (command.ClipRect.y - origin.y) * scale.y;
      const float clip_right = (command.ClipRect.z - origin.x) * scale.x;
      const float clip_bottom = (command.ClipRect.w - origin.y) * scale.y;
      if (clip_right <= clip_left || clip_bottom <= clip_top) continue;
      glScissor(static_cast<int>(clip_left),
                static_cast<int>(static_cast<float>(height) - clip_bottom),
                static_cast<int>(clip_right - clip_left), static_cast<int>(clip_bottom - clip_top));
      glBindTexture(GL_TEXTURE_2D,
                    static_cast<GLuint>(reinterpret_cast<std::uintptr_t>(command.TextureId)));
      if (command.VtxOffset != pointed) {
        pointed = command.VtxOffset;
        point_attributes(pointed);
      }
      glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(command.ElemCount), index_type,
                     reinterpret_cast<const void*>(
                         static_cast<std::uintptr_t>(command.IdxOffset * sizeof(ImDrawIdx))));
    }
  }
}

}  // namespace wobble

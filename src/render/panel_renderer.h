#ifndef WOBBLE_RENDER_PANEL_RENDERER_H
#define WOBBLE_RENDER_PANEL_RENDERER_H

#include <glad/gl.h>

#include <memory>

struct ImDrawData;

namespace wobble {

class ShaderProgram;

// Draws Dear ImGui's draw lists (the panel, its windows, the legend) with the GL functions glad
// loaded for the current context, in the window, headless (EGL) and in the page (WebGL 2) alike.
// Nothing here opens a GL library by name: ImGui's own OpenGL backend loads libGL.so.1 for
// itself, which an EGL-only machine (NVIDIA's driver in a container, a render node) does not
// have, and its panel then aborted.
//
// Draws as ImGui's shapes are meant to be drawn: positions in the display's pixels, one colour
// per vertex times the font atlas (linear filtering), alpha-blended over what is there, each
// command cut to its clip rectangle, no depth test or culling. The GL state it changes is put
// back afterwards. It names itself to the current ImGui context as its renderer
// (ImGuiIO::BackendRendererUserData), as ImGui's own backends do. Needs a current context for
// its whole life; throws ShaderError (the shader's file and the driver's log) when its shaders
// do not build.
class PanelRenderer {
 public:
  PanelRenderer();
  ~PanelRenderer();
  PanelRenderer(const PanelRenderer&) = delete;
  PanelRenderer& operator=(const PanelRenderer&) = delete;

  // The current ImGui context's font atlas, uploaded as a texture and named in the atlas as its
  // texture id. Again after the fonts change (another UI scale).
  void upload_fonts();
  // Draws `data` (ImGui::GetDrawData() after ImGui::Render()) into the bound framebuffer.
  void draw(const ImDrawData& data);

 private:
  std::unique_ptr<ShaderProgram> program_;
  GLint projection_ = -1, atlas_ = -1;
  GLuint font_texture_ = 0, vertex_array_ = 0, vertex_buffer_ = 0, index_buffer_ = 0;
};

}  // namespace wobble

#endif

#include "app/viewer/frame_loop.h"

#include <glad/gl.h>
// glad first: GLFW's backend must not include a GL header of its own.
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "app/viewer/viewer.h"
#include "render/offscreen_target.h"
#include "render/panel_renderer.h"

namespace wobble {

void read_shown_frame(int width, int height, RgbaImage& image) {
  image.width = width;
  image.height = height;
  glReadBuffer(GL_BACK);
  read_framebuffer_rgba(width, height, image.pixels);
}

RgbaImage read_shown_frame(int width, int height) {
  RgbaImage image;
  read_shown_frame(width, height, image);
  return image;
}

namespace {

// The built-in font is a pixel font on a 13-pixel grid: at 13, 26 or 39 px its outlines fall on
// whole pixels, but at a fractional scale (a pixel ratio of 1.25 or 1.5: Windows' scaling, a
// browser's zoom) one of its pixels is 1.23 or 1.54 of the screen's, its outlines fall between
// them, and the rasterizer greys each stroke's edge by its share of a pixel: the text blurred
// (measured at 1.25 and 1.5, with the glyphs on whole pixels: 51% and 43% of the panel's strong
// edges within one pixel, against 99% at whole ratios). Each glyph's pixels are made either ink
// or none, as a pixel font is scaled, so that its edges stay sharp.
void sharpen_glyphs(ImFontAtlas& atlas) {
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  atlas.GetTexDataAsAlpha8(&pixels, &width, &height);  // builds the atlas
  for (const ImFont* font : atlas.Fonts) {
    for (const ImFontGlyph& glyph : font->Glyphs) {
      const int x0 = static_cast<int>(std::lround(glyph.U0 * width)),
                x1 = static_cast<int>(std::lround(glyph.U1 * width)),
                y0 = static_cast<int>(std::lround(glyph.V0 * height)),
                y1 = static_cast<int>(std::lround(glyph.V1 * height));
      for (int y = std::max(y0, 0); y < std::min(y1, height); ++y) {
        for (int x = std::max(x0, 0); x < std::min(x1, width); ++x) {
          unsigned char& alpha = pixels[y * width + x];
          alpha = alpha >= 128 ? 255 : 0;
        }
      }
    }
  }
}

}  // namespace

FrameResult draw_frame(Viewer& viewer, FrameHost& host, FrameMeters& meters,
                       const FramePolicy& policy, float ui_scale) {
  FrameResult result;
  // 1. poll
  const PolledInput input = host.poll(viewer, meters);
  result.start = host.now();
  meters.start_frame(result.start);
  viewer.files().open_files(input.dropped_paths);  // a scene with its mesh, or a mesh
  const FrameSizes sizes = host.sizes();
  result.drawn = sizes.width > 0 && sizes.height > 0;  // a minimized window has no pixels
  // 2. new frame
  const bool imgui = policy.ui != FramePolicy::Ui::none;
  if (imgui) {
    host.begin_frame();
    ImGui::NewFrame();
    const ImGuiIO& io = ImGui::GetIO();
    viewer.handle_events(input.events, io.WantCaptureMouse, io.WantCaptureKeyboard, sizes.window);
    // 3. UI
    if (policy.ui == FramePolicy::Ui::panel) {
      PanelStats timings = policy.wall_clock_figures ? meters.timings() : PanelStats();
      timings.show_timings = policy.wall_clock_figures;
      viewer.build_ui(timings, ui_scale);
    } else {
      viewer.build_ui(PanelStats(), ui_scale, /*whole_panel=*/false);
    }
  } else {
    viewer.handle_events(input.events, false, false, sizes.window);
  }
  // 4. simulation
  if (policy.one_step_a_frame) {
    viewer.advance();
    result.new_state = true;
  } else {
    result.new_state = viewer.exchange(result.start, policy.frame_seconds);
  }
  if (policy.stop_on_failed_step && !viewer.session().step_warning().empty()) {
    // The frames and rows so far stay written; nothing else is.
    throw std::runtime_error("frame " + std::to_string(meters.frames) + ": " +
                             viewer.session().step_warning());
  }
  if (result.new_state) {
    const PanelStats shown = viewer.session().stats();
    meters.real_time.record(result.start, shown.simulated_seconds, shown.steps);
  }
  // 5. legend, render
  if (imgui) {
    viewer.build_legend(ui_scale);
    ImGui::Render();
  }
  const bool wanted = policy.output != nullptr && policy.output->wants(viewer);
  const auto read = [&host](RgbaImage& image) { host.read_picture(image); };
  if (result.drawn) {
    const bool draw = policy.draw_unwanted || wanted;
    if (draw) host.bind_target();
    const float pixel_ratio = sizes.window.x() > 0.0f ? sizes.width / sizes.window.x() : 1.0f;
    viewer.render(sizes.width, sizes.height, sizes.window, pixel_ratio,
                  sizes.mark_scale.value_or(pixel_ratio), draw);
    if (imgui && draw) {
      // A recording of the scene alone takes it before the panel goes over it.
      viewer.files().scene_drawn([&host] {
        RgbaImage image;
        host.read_picture(image);
        return image;
      });
      // The current ImGui context's renderer (ImGuiSession's), as ImGui's own backends keep it.
      if (auto* renderer = static_cast<PanelRenderer*>(ImGui::GetIO().BackendRendererUserData))
        renderer->draw(*ImGui::GetDrawData());
    }
  }
  // 6. outputs, present
  // F12 and the panel's PNG and record toggle (F9), from what is shown, panel included.
  const ViewerSession& session = viewer.session();
  viewer.files().write_frame(session.scene().name, session.shown_steps(), session.shown_time(),
                             result.drawn, [&host] {
                               RgbaImage image;
                               host.read_picture(image);
                               return image;
                             });
  if (wanted && result.drawn) policy.output->take(viewer, read);
  host.present("Wobble: " + session.scene().name);
  meters.end_frame(result.start, host.now());
  return result;
}

ImGuiSession::ImGuiSession(GLFWwindow* window, float scale, const Eigen::Vector2f& display) {
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini left in whatever folder wobble was started from
  apply_scale(scale);
  if (window != nullptr) {
    ImGui_ImplGlfw_InitForOpenGL(window, true);  // chains to the window's callbacks
    platform_ = true;
  } else {
    io.DisplaySize = ImVec2(display.x(), display.y());
    io.DeltaTime = 1.0f / 60.0f;
  }
  renderer_ = std::make_unique<PanelRenderer>();
}

void ImGuiSession::apply_scale(float scale) {
  scale_ = scale;
  ImGui::GetStyle() = ImGuiStyle();  // ImGui's own, as every session starts from it
  if (scale != 1.0f) ImGui::GetStyle().ScaleAllSizes(scale);
  // The built-in font at the pixel size the scale asks for (13 px at 1), drawn from its outlines:
  // magnifying the 13 px atlas would blur it on a high-DPI screen.
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  ImFontConfig font;
  font.SizePixels = std::round(13.0f * scale);
  const bool fractional = font.SizePixels != 13.0f * std::round(scale);
  // At a fractional scale each glyph's advance is rounded to whole pixels, so that every glyph
  // starts on a pixel boundary instead of a fraction into one, and its pixels are drawn once,
  // not three times across (ImGui's default for a font from outlines), so that its quad starts on
  // a whole pixel too: an atlas three times as wide put each glyph a third of a pixel over.
  font.PixelSnapH = fractional;
  if (fractional) font.OversampleH = 1;
  io.Fonts->AddFontDefault(&font);
  io.FontGlobalScale = 1.0f;
  if (fractional) sharpen_glyphs(*io.Fonts);
}

void ImGuiSession::rescale(float scale) {
  if (scale == scale_) return;
  apply_scale(scale);
  renderer_->upload_fonts();
}

void ImGuiSession::new_glfw_frame() {
  ImGui_ImplGlfw_NewFrame();
}

void GlfwFrameHost::begin_frame() {
  ImGuiSession::new_glfw_frame();
}

void GlfwFrameHost::bind_target() {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void GlfwFrameHost::read_picture(RgbaImage& image) {
  read_shown_frame(width_, height_, image);
}

ImGuiSession::~ImGuiSession() {
  renderer_.reset();
  if (platform_) ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

}  // namespace wobble

#include "app/web/run_browser.h"

// glad first: GLFW must not include a GL header of its own.
#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <emscripten.h>
#include <emscripten/html5.h>
#include <imgui.h>

#include <exception>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/cli/scene_catalog.h"
#include "app/viewer/frame_meters.h"
#include "app/viewer/viewer.h"
#include "platform/glfw_window.h"

namespace wobble {

namespace {

// What WebGL 2 lacks of the desktop's GL 3.3 core, and the renderer calls: glad leaves these
// null on a GL ES 3.0 context. Polygon modes (the wireframe over the surface) draw filled, and
// the springs' colour table (a buffer texture) stays empty; see shaders/es/spring_colors.frag.
void GLAD_API_PTR no_polygon_mode(GLenum, GLenum) {}
void GLAD_API_PTR no_texture_buffer(GLenum, GLenum, GLuint) {}

void fill_missing_gl_functions() {
  if (glad_glPolygonMode == nullptr) glad_glPolygonMode = no_polygon_mode;
  if (glad_glTexBuffer == nullptr) glad_glTexBuffer = no_texture_buffer;
}

// Everything a frame needs, kept alive after main returns.
struct BrowserApp {
  Viewer viewer;
  std::unique_ptr<GlfwWindow> window;
  FrameMeters meters;  // the panel's fps, UI frame time and real-time factor
  std::string title;
  long frames_drawn = 0;
};

double seconds_now() {
  return 1e-3 * emscripten_get_now();
}

// The canvas fills the page (index.html's style sheet); its drawing buffer follows that size.
void follow_page_size(GlfwWindow& window) {
  double css_width = 0.0, css_height = 0.0;
  emscripten_get_element_css_size("#canvas", &css_width, &css_height);
  int width = 0, height = 0;
  window.window_size(width, height);
  const int wanted_width = static_cast<int>(css_width),
            wanted_height = static_cast<int>(css_height);
  if (wanted_width > 0 && wanted_height > 0 && (wanted_width != width || wanted_height != height)) {
    glfwSetWindowSize(window.handle(), wanted_width, wanted_height);
  }
}

// One frame, in run_window.cpp's order.
void frame(BrowserApp& app) {
  Viewer& viewer = app.viewer;
  GlfwWindow& window = *app.window;
  follow_page_size(window);
  // 1. poll
  const std::vector<InputEvent> events = window.poll_events();
  const double now = seconds_now();
  app.meters.start_frame(now);
  // Files dropped on the page (copied into the page's file system by emscripten's GLFW).
  for (const std::string& path : window.take_dropped_paths())
    viewer.open_file(path);
  int width = 0, height = 0;
  window.window_size(width, height);
  const Eigen::Vector2f window_size(static_cast<float>(width), static_cast<float>(height));
  // 2. new frame
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  const ImGuiIO& io = ImGui::GetIO();
  viewer.handle_events(events, io.WantCaptureMouse, io.WantCaptureKeyboard, window_size);
  // 3. UI
  const float ui_scale = 1.0f;
  // A phone's screen is narrower than the panel: it opens folded (its title bar; a tap opens it),
  // so that the scene shows. The panel is the first window build_ui begins.
  if (app.frames_drawn == 0 && width < 600) ImGui::SetNextWindowCollapsed(true, ImGuiCond_Once);
  viewer.build_ui(app.meters.timings(), ui_scale);
  // 4. hand the changes to the simulation, take the latest state, step (on this thread)
  constexpr double frame_seconds = 1.0 / 60.0;
  if (viewer.exchange(now, frame_seconds)) {
    const PanelStats shown = viewer.stats();
    app.meters.real_time.record(now, shown.simulated_seconds, shown.steps);
  }
  viewer.build_legend(ui_scale);
  if ("Wobble: " + viewer.scene().name != app.title) {
    app.title = "Wobble: " + viewer.scene().name;
    window.set_title(app.title);
  }
  // 5. render; the browser shows the canvas once this returns
  ImGui::Render();
  if (width > 0 && height > 0) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    viewer.render(width, height, window_size, 1.0f);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  }
  app.meters.end_frame(now, seconds_now());
  // For the page and its tests (tests/web/page_check.py): frames drawn, and the steps they show.
  ++app.frames_drawn;
  EM_ASM(
      {
        Module.wobbleFrames = $0;
        Module.wobbleSteps = $1;
      },
      app.frames_drawn, static_cast<double>(viewer.shown_steps()));
}

void frame_or_report(void* app) {
  try {
    frame(*static_cast<BrowserApp*>(app));
  } catch (const std::exception& error) {
    std::cerr << "wobble: error: " << error.what() << "\n";
  }
}

}  // namespace

void run_browser(const CommandLine& command) {
  static std::unique_ptr<BrowserApp> app;  // lives for the page's life
  app.reset(new BrowserApp{open_viewer(command), nullptr, {}, {}, 0});
  app->viewer.show_notices(true);
  if (command.frames) app->viewer.set_step_limit(*command.frames);
  double css_width = 0.0, css_height = 0.0;
  emscripten_get_element_css_size("#canvas", &css_width, &css_height);
  app->window = std::make_unique<GlfwWindow>(css_width > 0 ? static_cast<int>(css_width) : 1280,
                                             css_height > 0 ? static_cast<int>(css_height) : 720,
                                             "Wobble: " + app->viewer.scene().name);
  fill_missing_gl_functions();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // nowhere to keep it
  ImGui_ImplGlfw_InitForOpenGL(app->window->handle(), true);
  ImGui_ImplOpenGL3_Init("#version 300 es");
  print_notes(app->viewer.scene(), std::cerr);
  app->viewer.attach_renderer();
  // 0 frames a second: the browser's own rate (requestAnimationFrame); do not simulate an
  // infinite loop, so main returns and the page keeps running.
  emscripten_set_main_loop_arg(frame_or_report, app.get(), 0, 0);
}

}  // namespace wobble

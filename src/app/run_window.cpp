#include "run_window.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <glad/gl.h>
#include <imgui.h>

#include <chrono>
#include <memory>

#include "image_outputs.h"
#include "instrument_csv.h"
#include "obj_sequence.h"
#include "platform/glfw_window.h"
#include "real_time_meter.h"
#include "render/offscreen_target.h"
#include "scene_catalog.h"
#include "viewer.h"
#include "window_saves.h"

namespace wobble {

namespace {

// ImGui with its GLFW and OpenGL 3 backends, scaled for high-DPI screens.
class WindowUi {
 public:
  WindowUi(GlfwWindow& window, float scale) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini left in whatever folder wobble was started from
    io.FontGlobalScale = scale;
    ImGui::GetStyle().ScaleAllSizes(scale);
    ImGui_ImplGlfw_InitForOpenGL(window.handle(), true);  // chains to the window's callbacks
    ImGui_ImplOpenGL3_Init("#version 330 core");
  }
  ~WindowUi() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  WindowUi(const WindowUi&) = delete;
  WindowUi& operator=(const WindowUi&) = delete;
};

}  // namespace

int run_window(const CommandLine& command, std::ostream& progress) {
  // Everything that can be refused is checked before a window appears.
  ImageOutputs outputs(command.screenshot, command.record, command.frames, progress);
  const ObjSequence obj_sequence(command.export_obj_sequence);
  Viewer viewer = open_viewer(command);
  InstrumentCsv instruments(command.convergence_csv, command.energy_csv, command.frames.value_or(0),
                            viewer.simulation().params().iterations);
  viewer.set_convergence_required(instruments.wants_convergence());
  instruments.start(viewer.simulation());

  std::string title = "Wobble: " + viewer.scene().name;
  GlfwWindow window(command.width, command.height, title);
  const float ui_scale = window.content_scale();
  WindowUi ui(window, ui_scale);
  print_notes(viewer.scene(), progress);
  viewer.attach_renderer();

  RgbaImage image;
  long frame = 0;
  RealTimeMeter real_time;
  const auto start = std::chrono::steady_clock::now();
  // Paused and untouched, the window waits for input instead of redrawing the same picture (88%
  // of a core under Xvfb before). ImGui settles a click or a hover over a few frames, so it
  // only waits after a few frames without input, and then at most half a second, which
  // also keeps a resize or an uncovered window redrawn.
  constexpr int settle_frames = 3;
  constexpr double idle_wait_seconds = 0.5;
  int quiet_frames = 0;
  while (!window.should_close() && !viewer.quit_requested()) {
    // 1. poll
    const bool idle = !viewer.animating() && quiet_frames >= settle_frames && !command.frames;
    const std::vector<InputEvent> events = window.poll_events(idle ? idle_wait_seconds : 0.0);
    quiet_frames = events.empty() ? quiet_frames + 1 : 0;
    // Files dropped on the window open as the picker's scenes do; the last one stays.
    for (const std::string& path : window.take_dropped_paths()) {
      viewer.open_file(path);
      quiet_frames = 0;
    }
    int window_width = 0, window_height = 0, width = 0, height = 0;
    window.window_size(window_width, window_height);
    window.framebuffer_size(width, height);
    const Eigen::Vector2f window_size(static_cast<float>(window_width),
                                      static_cast<float>(window_height));
    // 2. new frame
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    const ImGuiIO& io = ImGui::GetIO();
    viewer.handle_events(events, io.WantCaptureMouse, io.WantCaptureKeyboard, window_size);
    // 3. UI
    PanelStats timings;
    timings.fps = io.Framerate;
    timings.real_time_factor = static_cast<float>(real_time.real_time_factor());
    timings.steps_per_second = static_cast<float>(real_time.steps_per_second());
    viewer.build_ui(timings, ui_scale);
    // 4. step: one fixed dt per frame
    const long steps_before = viewer.simulation().steps_taken();
    viewer.advance();
    real_time.record(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
        viewer.simulation().time(), viewer.simulation().steps_taken());
    viewer.build_legend(ui_scale);
    obj_sequence.write(frame + 1, viewer.simulation().positions(), viewer.scene().network);
    // Rows for steps taken (none while paused), numbered by the simulation's step count.
    if (viewer.simulation().steps_taken() != steps_before) {
      instruments.record(viewer.simulation().steps_taken(), viewer.simulation());
    }
    // The title names the scene on show, also after the picker changed it.
    if ("Wobble: " + viewer.scene().name != title) {
      title = "Wobble: " + viewer.scene().name;
      window.set_title(title);
    }
    // 5. render
    ImGui::Render();
    if (width > 0 && height > 0) {  // a minimized window has no pixels
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      viewer.render(width, height, window_size, window_width > 0 ? width / window_size.x() : 1);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }
    if (viewer.take_screenshot_request() && width > 0 && height > 0) {
      // What the window shows, panel included.
      RgbaImage shot;
      shot.width = width;
      shot.height = height;
      glReadBuffer(GL_BACK);
      read_framebuffer_rgba(width, height, shot.pixels);
      const std::string path = unused_file_name(".", "wobble-" + viewer.scene().name, ".png");
      try {
        write_png(path, shot);
        viewer.saved("saved " + path);
      } catch (const std::exception& error) {
        viewer.saved(std::string("screenshot failed: ") + error.what());
      }
    }
    ++frame;
    const bool last = command.frames && frame >= *command.frames;
    // Without --frames the last frame is known only once the window closes, so a screenshot
    // keeps the latest one.
    const bool keep = outputs.wants(last) || (!command.frames && !command.screenshot.empty());
    if (keep && width > 0 && height > 0) {
      glReadBuffer(GL_BACK);
      image.width = width;
      image.height = height;
      read_framebuffer_rgba(width, height, image.pixels);
      if (outputs.wants(last)) outputs.write(frame, last, image);
    }
    // 6. swap
    window.swap_buffers();
    if (last) break;
  }
  if (!command.frames && !command.screenshot.empty() && !image.pixels.empty()) {
    outputs.write(frame, /*last=*/true, image);
  }
  viewer.detach_renderer();
  instruments.write();
  return 0;
}

}  // namespace wobble

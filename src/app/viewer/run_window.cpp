#include "app/viewer/run_window.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <glad/gl.h>
#include <imgui.h>

#include <chrono>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "app/cli/scene_catalog.h"
#include "app/outputs/image_outputs.h"
#include "app/outputs/instrument_csv.h"
#include "app/outputs/obj_sequence.h"
#include "app/outputs/run_statistics.h"
#include "app/viewer/frame_meters.h"
#include "app/viewer/viewer.h"
#include "platform/glfw_window.h"
#include "render/offscreen_target.h"

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

int run_window(const CommandLine& command, std::ostream& out, std::ostream& progress) {
  // Everything that can be refused is checked before a window appears.
  ImageOutputs outputs(command.screenshot, command.record, command.frames, progress);
  const ObjSequence obj_sequence(command.export_obj_sequence);
  Viewer viewer = open_viewer(command);
  InstrumentCsv instruments(command.convergence_csv, command.energy_csv, command.frames.value_or(0),
                            viewer.simulation().params().iterations);
  viewer.set_convergence_required(instruments.wants_convergence());
  viewer.show_notices(true);
  instruments.start(viewer.simulation());
  // Each step's rows, files and time, on the thread that took it, numbered by the step count.
  StepTimes step_times;
  viewer.set_step_observer([&](const Simulation& simulation) {
    const long step = simulation.steps_taken();
    obj_sequence.write(step, simulation.positions(), viewer.scene().network);
    instruments.record(step, simulation);
    if (command.stats) step_times.add(simulation.last_step_timing());
  });
  if (command.frames) viewer.set_step_limit(*command.frames);

  std::string title = "Wobble: " + viewer.scene().name;
  GlfwWindow window(command.width, command.height, title);
  const float ui_scale = window.content_scale();
  WindowUi ui(window, ui_scale);
  print_notes(viewer.scene(), progress);
  viewer.attach_renderer();
  // The simulation steps beside the UI from here on; a finished batch wakes a waiting UI.
  viewer.step_on_thread(GlfwWindow::wake);

  RgbaImage image;
  long recorded_steps = 0;
  viewer.record_window_into(".", progress);
  FrameMeters meters;               // the panel's fps, UI frame time and real-time factor
  std::vector<double> ui_frame_ms;  // --stats: each frame's own time while the simulation plays
  const auto start = std::chrono::steady_clock::now();
  const auto seconds_since_start = [&start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  // The UI draws at most this often where the display does not pace the swaps (Xvfb, a
  // compositor without vsync): more would only take cores from the steps.
  constexpr double frame_seconds = 1.0 / 60.0;
  // With nothing new to draw (paused and untouched, or a batch of steps still running) the
  // window waits for input or a finished batch instead of redrawing the same picture (88% of a
  // core under Xvfb before). ImGui settles a click or a hover over a few frames, so it only
  // waits after a few frames without input, and then at most half a second, which also keeps a
  // resize or an uncovered window redrawn.
  constexpr int settle_frames = 3;
  constexpr double idle_wait_seconds = 0.5;
  int quiet_frames = 0;
  try {
    while (!window.should_close() && !viewer.quit_requested()) {
      // 1. poll
      const bool nothing_new =
          quiet_frames >= settle_frames && (viewer.stepping() || !viewer.animating());
      const double frame_left = meters.last_frame + frame_seconds - seconds_since_start();
      const std::vector<InputEvent> events =
          nothing_new
              ? window.poll_events(idle_wait_seconds)
              : (frame_left > 0.0 ? window.wait_for_input(frame_left) : window.poll_events());
      quiet_frames = events.empty() ? quiet_frames + 1 : 0;
      const double now = seconds_since_start();
      meters.start_frame(now);
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
      viewer.build_ui(meters.timings(), ui_scale);
      // 4. hand the changes to the simulation and take the latest state (between its batches)
      const bool new_state = viewer.exchange(now, frame_seconds);
      const PanelStats shown = viewer.stats();
      if (new_state) meters.real_time.record(now, shown.simulated_seconds, shown.steps);
      if (command.frames && !viewer.step_warning().empty()) {
        // A scripted run stops where a step failed, as headless does.
        throw std::runtime_error("step " + std::to_string(shown.steps + 1) + ": " +
                                 viewer.step_warning());
      }
      viewer.build_legend(ui_scale);
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
      // F12 and the panel's record toggle (F9), from what the window shows, panel included.
      viewer.write_window_files(width > 0 && height > 0, [width, height] {
        RgbaImage drawn;
        drawn.width = width;
        drawn.height = height;
        glReadBuffer(GL_BACK);
        read_framebuffer_rgba(width, height, drawn.pixels);
        return drawn;
      });
      // --record: each step's state once, numbered by the step; --frames ends once step N is
      // drawn, and --screenshot is that picture.
      const bool last = command.frames && shown.steps >= *command.frames;
      const bool new_step = shown.steps != recorded_steps;
      const bool keep =
          (new_step && outputs.wants(last)) || (!command.frames && !command.screenshot.empty());
      if (keep && width > 0 && height > 0) {
        glReadBuffer(GL_BACK);
        image.width = width;
        image.height = height;
        read_framebuffer_rgba(width, height, image.pixels);
        if (new_step && outputs.wants(last)) outputs.write(shown.steps, last, image);
      }
      recorded_steps = shown.steps;
      // 6. swap
      window.swap_buffers();
      // The UI's own time for a frame, from input to a picture, while the simulation plays:
      // what a drag or a click waits for, and never a step.
      const double done = seconds_since_start();
      meters.end_frame(now, done);
      if (command.stats && !viewer.paused()) ui_frame_ms.push_back(1e3 * (done - now));
      if (last) break;
    }
    viewer.finish_steps();
  } catch (...) {
    // The rows and files of the steps so far are kept, as headless keeps them.
    viewer.stop_stepping();
    instruments.write();
    throw;
  }
  if (!command.frames && !command.screenshot.empty() && !image.pixels.empty()) {
    outputs.write(recorded_steps, /*last=*/true, image);
  }
  viewer.detach_renderer();
  instruments.write();
  if (command.stats) {
    nlohmann::ordered_json stats =
        run_statistics(viewer.simulation(), viewer.scene(), viewer.stats().steps, step_times);
    stats["ui_frame_ms_median"] = median(ui_frame_ms);
    stats["ui_frames"] = ui_frame_ms.size();
    stats["real_time"] = viewer.real_time();
    stats["width"] = command.width;
    stats["height"] = command.height;
    out << stats.dump() << "\n";
  }
  return 0;
}

}  // namespace wobble

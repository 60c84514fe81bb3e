#include "app/window/run_window.h"

#include <glad/gl.h>

#include <chrono>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "app/cli/scene_catalog.h"
#include "app/outputs/image_outputs.h"
#include "app/outputs/instrument_csv.h"
#include "app/outputs/obj_sequence.h"
#include "app/outputs/run_statistics.h"
#include "app/outputs/step_outputs.h"
#include "app/viewer/frame_loop.h"
#include "app/viewer/viewer.h"
#include "platform/glfw_window.h"

namespace wobble {

namespace {

// The window as draw_frame's host: GLFW's input, sizes and swaps, and a clock from the start.
class WindowHost : public GlfwFrameHost {
 public:
  WindowHost(GlfwWindow& window, std::string title)
      : window_(window), start_(std::chrono::steady_clock::now()), title_(std::move(title)) {}

  PolledInput poll(const Viewer& viewer, const FrameMeters& meters) override {
    // With nothing new to draw (paused and untouched, or a batch of steps still running) the
    // window waits for input or a finished batch instead of redrawing the same picture, which
    // would keep a core busy for nothing. ImGui settles a click or a hover over a few frames, so it
    // only waits after a few frames without input, and then at most half a second, which also keeps
    // a resize or an uncovered window redrawn. Otherwise the UI draws at most frame_seconds
    // apart where the display does not pace the swaps (Xvfb, a compositor without vsync): more
    // would only take cores from the steps.
    const bool nothing_new =
        quiet_frames_ >= settle_frames && (viewer.session().stepping() || !viewer.animating());
    const double frame_left = meters.last_frame + frame_seconds - now();
    PolledInput input;
    input.events = nothing_new ? window_.poll_events(idle_wait_seconds)
                               : (frame_left > 0.0 ? window_.wait_for_input(frame_left)
                                                   : window_.poll_events());
    input.dropped_paths = window_.take_dropped_paths();
    quiet_frames_ = input.events.empty() && input.dropped_paths.empty() ? quiet_frames_ + 1 : 0;
    return input;
  }
  double now() const override {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  FrameSizes sizes() override {
    int window_width = 0, window_height = 0;
    window_.window_size(window_width, window_height);
    window_.framebuffer_size(width_, height_);
    FrameSizes sizes;
    sizes.width = width_;
    sizes.height = height_;
    sizes.window =
        Eigen::Vector2f(static_cast<float>(window_width), static_cast<float>(window_height));
    return sizes;
  }
  void present(const std::string& title) override {
    // The title names the scene on show, also after the picker changed it.
    if (title != title_) window_.set_title(title_ = title);
    window_.swap_buffers();
  }

  static constexpr double frame_seconds = 1.0 / 60.0;

 private:
  static constexpr int settle_frames = 3;
  static constexpr double idle_wait_seconds = 0.5;
  GlfwWindow& window_;
  const std::chrono::steady_clock::time_point start_;
  std::string title_;
  int quiet_frames_ = 0;
};

// --record and --screenshot from the window: each step's state once, numbered by the step;
// --frames ends once step N is drawn, and --screenshot is that picture (without --frames, the
// last picture the window showed).
class WindowPictures : public PictureOutput {
 public:
  WindowPictures(const CommandLine& command, ImageOutputs& outputs)
      : command_(command), outputs_(outputs) {}

  bool wants(const Viewer& viewer) override {
    const long steps = viewer.session().stats().steps;
    last_ = command_.frames && steps >= *command_.frames;
    new_step_ = steps != recorded_steps_;
    recorded_steps_ = steps;
    recorded_time_ = viewer.session().shown_time();
    return (new_step_ && outputs_.wants(last_)) ||
           (!command_.frames && !command_.screenshot.empty());
  }
  void take(const Viewer& viewer, const std::function<void(RgbaImage&)>& read) override {
    read(image_);
    if (new_step_ && outputs_.wants(last_)) {
      outputs_.write(recorded_steps_, last_, image_, viewer.session().shown_time());
    }
  }
  // Step N of --frames is drawn: the run ends.
  bool last() const { return last_; }
  void write_screenshot() {
    if (!command_.frames && !command_.screenshot.empty() && !image_.pixels.empty()) {
      outputs_.write(recorded_steps_, /*last=*/true, image_, recorded_time_);
    }
  }

 private:
  const CommandLine& command_;
  ImageOutputs& outputs_;
  RgbaImage image_;
  long recorded_steps_ = 0;
  FrameTime recorded_time_;
  bool last_ = false, new_step_ = false;
};

}  // namespace

int run_window(const CommandLine& command, std::ostream& out, std::ostream& progress) {
  // Everything that can be refused is checked before a window appears.
  ImageOutputs outputs(command.screenshot, command.record, command.frames, progress);
  const ObjSequence obj_sequence(command.export_obj_sequence);
  Viewer viewer = open_viewer(command);
  InstrumentCsv instruments(command.convergence_csv, command.energy_csv, command.frames.value_or(0),
                            viewer.session().simulation().params().iterations);
  viewer.session().set_convergence_required(instruments.wants_convergence());
  viewer.files().show_notices(true);
  instruments.start(viewer.session().simulation());
  // Each step's files, rows and time, on the thread that took it, numbered by the step count.
  StepOutputs step_outputs(obj_sequence, instruments, command.stats);
  viewer.session().set_step_observer(
      [&](const Simulation& simulation) { step_outputs.after_step(simulation); });
  if (command.frames) viewer.session().set_step_limit(*command.frames);

  const std::string title = "Wobble: " + viewer.session().scene().name;
  GlfwWindow window(command.width, command.height, title);
  const float ui_scale = window.content_scale();
  ImGuiSession ui(window.handle(), ui_scale);
  print_notes(viewer.session().scene(), progress);
  viewer.drawing().attach_renderer();
  // The simulation steps beside the UI from here on; a finished batch wakes a waiting UI.
  viewer.session().step_on_thread(GlfwWindow::wake);
  viewer.files().record_into(".", progress);

  WindowHost host(window, title);
  WindowPictures pictures(command, outputs);
  FramePolicy policy;
  policy.stop_on_failed_step = command.frames.has_value();  // a scripted run, as headless
  policy.output = &pictures;
  policy.frame_seconds = WindowHost::frame_seconds;
  FrameMeters meters;               // the panel's fps, UI frame time and real-time factor
  std::vector<double> ui_frame_ms;  // --stats: each frame's own time while the simulation plays
  try {
    while (!window.should_close() && !viewer.panel().quit_requested()) {
      const FrameResult frame = draw_frame(viewer, host, meters, policy, ui_scale);
      // The UI's own time for a frame, from input to a picture, while the simulation plays:
      // what a drag or a click waits for, and never a step.
      if (command.stats && !viewer.panel().paused())
        ui_frame_ms.push_back(1e3 * (host.now() - frame.start));
      if (pictures.last()) break;
    }
    viewer.finish_steps();
  } catch (...) {
    // The rows and files of the steps so far are kept, as headless keeps them.
    viewer.session().stop_stepping();
    instruments.write();
    throw;
  }
  pictures.write_screenshot();
  outputs.finish();  // the video's index; a failure above completes it in its destructor
  viewer.drawing().detach_renderer();
  instruments.write();
  if (command.stats) {
    nlohmann::ordered_json stats =
        run_statistics(viewer.session().simulation(), viewer.session().scene(),
                       viewer.session().stats().steps, step_outputs.times());
    stats["ui_frame_ms_median"] = median(ui_frame_ms);
    stats["ui_frames"] = ui_frame_ms.size();
    stats["real_time"] = viewer.panel().real_time();
    stats["width"] = command.width;
    stats["height"] = command.height;
    out << stats.dump() << "\n";
  }
  return 0;
}

}  // namespace wobble

#include "app/headless/render_offscreen.h"

#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>

#include "app/viewer/frame_loop.h"
#include "platform/egl_context.h"
#include "render/offscreen_target.h"

namespace wobble {

namespace {

// Frees the viewer's GL objects before the context goes, however the loop ends.
struct RendererAttachment {
  explicit RendererAttachment(Viewer& viewer) : viewer(viewer) { viewer.attach_renderer(); }
  ~RendererAttachment() { viewer.detach_renderer(); }
  Viewer& viewer;
};

// An offscreen target as draw_frame's host: no input, a clock that counts frames, one step a
// frame, and the picture read back for the images and files a frame writes.
class OffscreenHost : public FrameHost {
 public:
  OffscreenHost(OffscreenTarget& target, const OffscreenOptions& options, bool imgui,
                ImageOutputs* outputs, OffscreenReport* report)
      : target_(target), options_(options), imgui_(imgui), outputs_(outputs), report_(report) {
    image_.width = options.width;
    image_.height = options.height;
  }

  std::vector<InputEvent> poll(const Viewer& /*viewer*/, const FrameMeters& /*meters*/) override {
    ++frame_;
    return {};
  }
  // Nothing in the images depends on the wall clock.
  double now() const override { return static_cast<double>(frame_) / 60.0; }
  void sizes(int& width, int& height, Eigen::Vector2f& window) override {
    width = options_.width;
    height = options_.height;
    window = Eigen::Vector2f(static_cast<float>(width), static_cast<float>(height));
  }
  bool uses_imgui() const override { return imgui_; }
  // Without --ui, only what ImGui draws over the scene: the split view's labels and the legend.
  bool builds_panel() const override { return options_.ui; }
  PanelStats timings(const FrameMeters& /*meters*/) const override {
    PanelStats timings;
    timings.show_timings = false;  // the wall clock stays out of the pixels
    return timings;
  }
  bool advance(Viewer& viewer, double /*now*/) override {
    viewer.advance();
    // A rolled-back step stops the run: the frames so far stay written, nothing else is.
    const StepStatus status = viewer.simulation().last_step_status();
    if (status != StepStatus::ok) {
      throw std::runtime_error("frame " + std::to_string(frame_) + ": " +
                               Simulation::describe(status));
    }
    return true;
  }
  // Only the frames an output reads are drawn: the last, and those --record or
  // --screenshot-every take. The others are laid out all the same (the camera frames the shape
  // as it would have), so the pictures drawn are the same pixels.
  bool bind_target() override {
    const bool last = frame_ == options_.frames;
    pictured_ = last || (outputs_ != nullptr && outputs_->wants(last));
    if (!pictured_) return false;
    render_start_ = std::chrono::steady_clock::now();
    target_.bind();
    return true;
  }
  void present(Viewer& viewer, bool /*drawn*/) override {
    if (!pictured_) return;
    const bool last = frame_ == options_.frames;
    target_.read_rgba(image_.pixels);
    if (report_) {
      report_->render_ms.push_back(std::chrono::duration<double, std::milli>(
                                       std::chrono::steady_clock::now() - render_start_)
                                       .count());
    }
    if (outputs_ != nullptr && outputs_->wants(last)) {
      // Every step is a frame: a video of them plays at 1/dt frames a second.
      const Simulation& simulation = viewer.simulation();
      outputs_->write(frame_, last, image_, FrameTime{simulation.time(), simulation.params().dt});
    }
  }

  RgbaImage& image() { return image_; }

 private:
  OffscreenTarget& target_;
  const OffscreenOptions& options_;
  const bool imgui_;
  ImageOutputs* outputs_;
  OffscreenReport* report_;
  long frame_ = 0;
  bool pictured_ = false;  // this frame is drawn and read back
  RgbaImage image_;
  std::chrono::steady_clock::time_point render_start_;
};

}  // namespace

RgbaImage render_offscreen(Viewer& viewer, const OffscreenOptions& options, ImageOutputs* outputs,
                           OffscreenReport* report) {
  EglContext context;
  OffscreenTarget target(options.width, options.height);
  RendererAttachment attachment(viewer);
  // ImGui draws the panel, the split view's corner labels even without the panel, and the colour
  // legend whenever the shape is coloured by a quantity.
  const bool legend = viewer.color_by() != ColorQuantity::material;
  const bool imgui = options.ui || viewer.has_overlays() || legend;
  std::unique_ptr<ImGuiSession> ui;
  if (imgui) {
    ui = std::make_unique<ImGuiSession>(
        nullptr, 1.0f,
        Eigen::Vector2f(static_cast<float>(options.width), static_cast<float>(options.height)));
  }
  if (report) {
    report->context = context.description();
    report->driver = context.driver();
  }

  OffscreenHost host(target, options, imgui, outputs, report);
  FrameMeters meters;
  for (long frame = 1; frame <= options.frames; ++frame)
    draw_frame(viewer, host, meters, 1.0f);
  return host.image();
}

}  // namespace wobble

#include "app/headless/render_offscreen.h"

#include <chrono>
#include <memory>
#include <string>

#include "app/viewer/frame_loop.h"
#include "platform/egl_context.h"
#include "render/offscreen_target.h"

namespace wobble {

namespace {

// Frees the viewer's GL objects before the context goes, however the loop ends.
struct RendererAttachment {
  explicit RendererAttachment(Viewer& viewer) : viewer(viewer) {
    viewer.drawing().attach_renderer();
  }
  ~RendererAttachment() { viewer.drawing().detach_renderer(); }
  Viewer& viewer;
};

// An offscreen target as draw_frame's host: no input, a clock that counts frames, and the
// framebuffer object drawn into and read back. How long a picture took (bind to read-back) goes to
// the report.
class OffscreenHost : public FrameHost {
 public:
  OffscreenHost(OffscreenTarget& target, const OffscreenOptions& options, OffscreenReport* report)
      : target_(target), options_(options), report_(report) {}

  PolledInput poll(const Viewer& /*viewer*/, const FrameMeters& /*meters*/) override {
    ++frame_;
    return {};
  }
  // Nothing in the images depends on the wall clock.
  double now() const override { return static_cast<double>(frame_) / 60.0; }
  FrameSizes sizes() override {
    FrameSizes sizes;
    sizes.width = options_.width;
    sizes.height = options_.height;
    sizes.window =
        Eigen::Vector2f(static_cast<float>(sizes.width), static_cast<float>(sizes.height));
    return sizes;
  }
  void begin_frame() override {}
  void bind_target() override {
    render_start_ = std::chrono::steady_clock::now();
    target_.bind();
  }
  void read_picture(RgbaImage& image) override {
    image.width = options_.width;
    image.height = options_.height;
    target_.read_rgba(image.pixels);
    if (report_) {
      report_->render_ms.push_back(std::chrono::duration<double, std::milli>(
                                       std::chrono::steady_clock::now() - render_start_)
                                       .count());
    }
  }
  void present(const std::string& /*title*/) override {}

 private:
  OffscreenTarget& target_;
  const OffscreenOptions& options_;
  OffscreenReport* report_;
  long frame_ = 0;
  std::chrono::steady_clock::time_point render_start_;
};

// The headless images: the last frame's picture, and those --record or --screenshot-every take,
// each step a frame (a video of them plays at 1/dt frames a second).
class OffscreenPictures : public PictureOutput {
 public:
  OffscreenPictures(long frames, ImageOutputs* outputs) : frames_(frames), outputs_(outputs) {}

  bool wants(const Viewer& /*viewer*/) override {
    ++frame_;
    last_ = frame_ == frames_;
    return last_ || (outputs_ != nullptr && outputs_->wants(last_));
  }
  void take(const Viewer& viewer, const std::function<void(RgbaImage&)>& read) override {
    read(image_);
    if (outputs_ != nullptr && outputs_->wants(last_)) {
      const Simulation& simulation = viewer.session().simulation();
      outputs_->write(frame_, last_, image_, FrameTime{simulation.time(), simulation.params().dt});
    }
  }
  RgbaImage& image() { return image_; }

 private:
  const long frames_;
  ImageOutputs* outputs_;
  long frame_ = 0;
  bool last_ = false;
  RgbaImage image_;
};

}  // namespace

RgbaImage render_offscreen(Viewer& viewer, const OffscreenOptions& options, ImageOutputs* outputs,
                           OffscreenReport* report) {
  EglContext context;
  OffscreenTarget target(options.width, options.height);
  RendererAttachment attachment(viewer);
  // ImGui draws the panel, the split view's corner labels even without the panel, and the colour
  // legend whenever the shape is coloured by a quantity.
  const bool legend = viewer.panel().color_by() != ColorQuantity::material;
  const bool imgui = options.ui || viewer.session().has_overlays() || legend;
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

  OffscreenHost host(target, options, report);
  OffscreenPictures pictures(options.frames, outputs);
  FramePolicy policy;
  // Without --ui, only what ImGui draws over the scene: the split view's labels and the legend.
  policy.ui = !imgui ? FramePolicy::Ui::none
                     : (options.ui ? FramePolicy::Ui::panel : FramePolicy::Ui::overlays);
  policy.wall_clock_figures = false;  // the wall clock stays out of the pixels
  policy.one_step_a_frame = true;
  policy.stop_on_failed_step = true;
  policy.draw_unwanted = false;
  policy.output = &pictures;
  FrameMeters meters;
  for (long frame = 1; frame <= options.frames; ++frame)
    draw_frame(viewer, host, meters, policy, 1.0f);
  return pictures.image();
}

}  // namespace wobble

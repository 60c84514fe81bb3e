#include "app/headless/render_offscreen.h"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <chrono>
#include <stdexcept>
#include <string>

#include "platform/egl_context.h"
#include "render/offscreen_target.h"

namespace wobble {

namespace {

// An ImGui context driven by hand: no platform backend, a fixed display size and a fixed frame
// time, so the panel is laid out the same way on every run.
class HeadlessUi {
 public:
  HeadlessUi(int width, int height) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
    io.DeltaTime = 1.0f / 60.0f;
    ImGui_ImplOpenGL3_Init("#version 330 core");
  }
  ~HeadlessUi() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext();
  }
  HeadlessUi(const HeadlessUi&) = delete;
  HeadlessUi& operator=(const HeadlessUi&) = delete;
};

// Frees the viewer's GL objects before the context goes, however the loop ends.
struct RendererAttachment {
  explicit RendererAttachment(Viewer& viewer) : viewer(viewer) { viewer.attach_renderer(); }
  ~RendererAttachment() { viewer.detach_renderer(); }
  Viewer& viewer;
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
  std::unique_ptr<HeadlessUi> ui;
  if (options.ui || viewer.has_overlays() || legend) {
    ui = std::make_unique<HeadlessUi>(options.width, options.height);
  }
  if (report) report->context = context.description();

  const Eigen::Vector2f size(static_cast<float>(options.width), static_cast<float>(options.height));
  PanelStats timings;
  timings.show_timings = false;  // the wall clock stays out of the pixels
  RgbaImage image;
  image.width = options.width;
  image.height = options.height;
  for (long frame = 1; frame <= options.frames; ++frame) {
    const bool last = frame == options.frames;
    if (ui) {
      ImGui_ImplOpenGL3_NewFrame();
      ImGui::NewFrame();
      if (options.ui) {
        viewer.build_ui(timings, 1.0f);
      } else {
        viewer.draw_overlays(1.0f);
      }
    }
    viewer.advance();
    // A rolled-back step stops the run: the frames so far stay written, nothing else is.
    const StepStatus status = viewer.simulation().last_step_status();
    if (status != StepStatus::ok) {
      throw std::runtime_error("frame " + std::to_string(frame) + ": " +
                               Simulation::describe(status));
    }
    if (options.obj_sequence != nullptr) {
      options.obj_sequence->write(frame, viewer.simulation().positions(), viewer.scene().network);
    }
    if (options.instruments != nullptr) options.instruments->record(frame, viewer.simulation());
    if (report) report->times.add(viewer.simulation().last_step_timing());
    if (ui) viewer.build_legend(1.0f);

    const auto start = std::chrono::steady_clock::now();
    target.bind();
    viewer.render(options.width, options.height, size, 1.0f);
    if (ui) {
      ImGui::Render();
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }
    const bool read = last || (outputs != nullptr && outputs->wants(last));
    if (read) {
      target.read_rgba(image.pixels);
    } else {
      target.finish();
    }
    if (report) {
      report->render_ms.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count());
    }
    if (outputs != nullptr && outputs->wants(last)) outputs->write(frame, last, image);
  }
  return image;
}

}  // namespace wobble

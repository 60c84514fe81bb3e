#ifndef WOBBLE_APP_VIEWER_FRAME_LOOP_H
#define WOBBLE_APP_VIEWER_FRAME_LOOP_H

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/viewer/frame_meters.h"
#include "io/png_image.h"
#include "platform/input_event.h"

struct GLFWwindow;

namespace wobble {

class PanelRenderer;
class Viewer;

// What one poll brought: the input since the last frame and the files dropped on the window or
// the page.
struct PolledInput {
  std::vector<InputEvent> events;
  std::vector<std::string> dropped_paths;
};

// The picture's size in pixels, the window's in the units of the mouse events, and the
// picture's pixels per pixel of a mark's size (pin dots, the held vertex): the pixel ratio where
// window units are the screen's points; the page, whose window units are device pixels, gives
// its device pixel ratio so that marks keep their CSS size (unset: the pixel ratio).
struct FrameSizes {
  int width = 0, height = 0;
  Eigen::Vector2f window = Eigen::Vector2f::Zero();
  std::optional<float> mark_scale;
};

// The platform under draw_frame, and only that: where input comes from, the clock, the sizes,
// ImGui's platform part, the target drawn into, reading it back and showing it. The window
// (app/window/run_window.cpp), the page (app/web/run_browser.cpp) and headless
// (app/headless/render_offscreen.cpp) each are one (MuJoCo's simulate over its platform
// adapter, Polyscope's engine over GLFW or EGL). How the simulation moves on and what a run
// keeps of its pictures are the loop's (FramePolicy), never a host's.
class FrameHost {
 public:
  virtual ~FrameHost() = default;
  // 1. The input since the last frame, after waiting as the host waits (the window waits while
  // nothing changes; the page and headless never wait).
  virtual PolledInput poll(const Viewer& viewer, const FrameMeters& meters) = 0;
  // The loop's clock (s).
  virtual double now() const = 0;
  virtual FrameSizes sizes() = 0;
  // 2. The platform's part of a new frame (GLFW's for ImGui: display size, mouse, keys), before
  // ImGui's new frame.
  virtual void begin_frame() = 0;
  // 5. Bind the target the frame is drawn into: the default framebuffer, or an offscreen one.
  virtual void bind_target() = 0;
  // The picture just drawn, read back into `image` (resized, its buffer kept).
  virtual void read_picture(RgbaImage& image) = 0;
  // 6. Show the frame (swap), or nothing where the browser shows it; `title` names the scene on
  // show (the window's title).
  virtual void present(const std::string& title) = 0;
};

// A host that draws into the default framebuffer of a GLFW window (the window, the page): GLFW's
// part of ImGui's new frame, and the picture read back before it is shown, width_ by height_
// pixels of the drawing buffer as the host's sizes() last found them.
class GlfwFrameHost : public FrameHost {
 public:
  void begin_frame() override;
  void bind_target() override;
  void read_picture(RgbaImage& image) override;

 protected:
  int width_ = 0, height_ = 0;
};

// What a run keeps of its pictures (--record, --screenshot, the headless images), handed to the
// loop by the run. The viewer's own files (F12, the panel's PNG and record toggle) the loop
// writes itself.
class PictureOutput {
 public:
  virtual ~PictureOutput() = default;
  // Whether this frame's picture is read back, once the simulation moved on (step 4).
  virtual bool wants(const Viewer& viewer) = 0;
  // The frame's picture, drawn and wanted; `read` reads it back into an image.
  virtual void take(const Viewer& viewer, const std::function<void(RgbaImage& image)>& read) = 0;
};

// How the loop runs for a mode: what ImGui draws, how the simulation moves on, when a run stops.
struct FramePolicy {
  // The whole panel; only what ImGui draws over the scene (the split view's labels, the legend,
  // the plots: headless images without --ui); or no ImGui at all.
  enum class Ui { panel, overlays, none } ui = Ui::panel;
  // The panel's figures from the wall clock (fps, the real-time factor). Headless shows none, so
  // that its pixels never depend on the clock.
  bool wall_clock_figures = true;
  // Batches of steps beside the UI (Viewer::exchange: the window's stepping thread, the page's
  // one thread), or exactly one step a frame (Viewer::advance: headless).
  bool one_step_a_frame = false;
  // A step the simulation rolled back ends the run (headless, and the window's --frames), with
  // the frame and the reason: runtime_error.
  bool stop_on_failed_step = false;
  // Draw every frame (a window or page someone looks at), or only the frames `output` wants,
  // laying the others out as if drawn (the camera's framing, the panel), so that the pictures
  // drawn are the same pixels: most of a headless run's time.
  bool draw_unwanted = true;
  PictureOutput* output = nullptr;  // not owned; none: nothing is kept
  // Seconds a frame of the window or page is given (the real-time mode's batch fits in it).
  double frame_seconds = 1.0 / 60.0;
};

// The picture just drawn into the default framebuffer, read back before it is shown (the window's
// swap, the page's return to the browser): what the window and the page read their pictures from.
// `image` is resized to width by height pixels, its buffer kept.
void read_shown_frame(int width, int height, RgbaImage& image);
RgbaImage read_shown_frame(int width, int height);

// What one frame did.
struct FrameResult {
  bool new_state = false;  // the frame shows a state it did not show before
  bool drawn = false;      // it had pixels to draw into (a minimized window has none)
  double start = 0.0;      // when it started, on the host's clock (s)
};

// One frame, in this order:
//   1. poll            the host's input; dropped files open as the picker's scenes do
//   2. new frame       the host's platform part, ImGui's; the input to the viewer
//   3. UI              the panel (or only the overlays)
//   4. simulation      a batch exchanged or one step (the policy); a failed step may stop the
//                      run; the real-time meter
//   5. legend, render  the colour legend, the scene, then ImGui over it
//   6. outputs,        the viewer's files (F12, record) and the run's pictures, read back from
//      present         the host; then the host shows the picture
// `ui_scale` multiplies the panel's own UI scale (the screen's content scale).
FrameResult draw_frame(Viewer& viewer, FrameHost& host, FrameMeters& meters,
                       const FramePolicy& policy, float ui_scale);

// ImGui for the life of a loop, set up the one way every host needs it: no imgui.ini left
// anywhere, fonts and sizes scaled by `scale`, Wobble's own renderer (render/panel_renderer.h,
// through the GL functions glad loaded, so nothing opens libGL.so.1), and GLFW's platform
// backend for `window`; with no window (headless), a fixed `display` size and frame
// time instead, so that the panel is laid out the same on every run.
class ImGuiSession {
 public:
  ImGuiSession(GLFWwindow* window, float scale,
               const Eigen::Vector2f& display = Eigen::Vector2f::Zero());
  ~ImGuiSession();
  // GLFW's part of a new frame, for a host whose session has a window.
  static void new_glfw_frame();
  // Sizes and fonts for another scale (a page moved to a screen of another pixel ratio, or
  // zoomed): the style as it was made, scaled once, and the font drawn again at its pixel size
  // rather than magnified, so that text stays sharp. Between frames only.
  void rescale(float scale);
  float scale() const { return scale_; }
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;

 private:
  void apply_scale(float scale);
  std::unique_ptr<PanelRenderer> renderer_;
  bool platform_ = false;
  float scale_ = 1.0f;
};

}  // namespace wobble

#endif

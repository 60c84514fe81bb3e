#ifndef WOBBLE_APP_VIEWER_FRAME_LOOP_H
#define WOBBLE_APP_VIEWER_FRAME_LOOP_H

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "app/viewer/frame_meters.h"
#include "io/png_image.h"
#include "platform/input_event.h"

struct GLFWwindow;

namespace wobble {

class PanelRenderer;
class Viewer;

// What differs between the window (app/viewer/run_window.cpp), the page (app/web/run_browser.cpp)
// and headless (app/headless/render_offscreen.cpp): where input comes from, the clock, how the
// simulation moves on in a frame, where the picture is drawn and where it goes. The frame's
// order is draw_frame's alone, the same for all three (MuJoCo's simulate over its platform
// adapter, Polyscope's engine over GLFW or EGL).
class FrameHost {
 public:
  virtual ~FrameHost() = default;
  // 1. The input since the last frame, after waiting as the host waits (the window waits while
  // nothing changes; the page and headless never wait).
  virtual std::vector<InputEvent> poll(const Viewer& viewer, const FrameMeters& meters) = 0;
  // Files dropped on the window or the page since the last poll.
  virtual std::vector<std::string> take_dropped_paths() { return {}; }
  // The loop's clock (s).
  virtual double now() const = 0;
  // The picture's size in pixels and the window's in points (the page and headless: the same).
  virtual void sizes(int& width, int& height, Eigen::Vector2f& window) = 0;
  // The picture's pixels per pixel of a mark's size (pin dots, the held vertex): `pixel_ratio`
  // (the picture's pixels per window point) where points are the screen's own; the page, whose
  // window units are device pixels, gives its device pixel ratio, so marks keep their CSS size.
  virtual float mark_scale(float pixel_ratio) const { return pixel_ratio; }
  // Whether ImGui runs this frame (headless: only when the panel, the split view's labels or a
  // legend show), and whether the whole panel is built or only the overlays (headless --ui).
  virtual bool uses_imgui() const { return true; }
  virtual bool builds_panel() const { return true; }
  // 2. The platform backend's part of ImGui's new frame (GLFW's: display size, mouse, keys).
  virtual void new_platform_frame() {}
  // Just before the panel is built, after ImGui's new frame (the page folds the panel on a
  // phone's first frame).
  virtual void before_panel() {}
  // The panel's figures from the wall clock (headless shows none, to keep the pixels the same).
  virtual PanelStats timings(const FrameMeters& meters) const { return meters.timings(); }
  // 4. The simulation's part of the frame: hand the UI's changes over and take the latest state
  // (a batch on the stepping thread in the window, steps on this thread in the page), or take
  // exactly one step (headless). Returns whether a new state is shown.
  virtual bool advance(Viewer& viewer, double now) = 0;
  // The window's title, whenever the scene on show changes.
  virtual void set_title(const std::string& /*title*/) {}
  // 5. Where the frame is drawn: the default framebuffer, or an offscreen target. Returns whether
  // the frame is drawn at all: headless, a frame whose picture no output reads is laid out (the
  // camera's framing, the panel) but not drawn, which is most of a headless run's time.
  virtual bool bind_target() = 0;
  // 6. The picture drawn: read back what is wanted (files, images), then show it (swap) or not.
  virtual void present(Viewer& viewer, bool drawn) = 0;
};

// The picture just drawn into the default framebuffer, read back before it is shown (the window's
// swap, the page's return to the browser): what the window and the page write their PNGs from.
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
//   2. new frame       ImGui's (the platform's part from the host); the input to the viewer
//   3. UI              the panel (or only the overlays)
//   4. simulation      the host's advance; the real-time meter
//   5. legend, render  the colour legend, the title, the scene, then ImGui over it
//   6. present         the host reads back and shows the picture
// `ui_scale` multiplies the panel's own UI scale (the screen's content scale).
FrameResult draw_frame(Viewer& viewer, FrameHost& host, FrameMeters& meters, float ui_scale);

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

#ifndef WOBBLE_APP_WEB_PAGE_HOST_H
#define WOBBLE_APP_WEB_PAGE_HOST_H

// The page as draw_frame's host (run_browser.cpp): emscripten's GLFW for input, the canvas's
// size and pixel ratio, the browser's clock, and the figures the page's tests read.
// glad first: GLFW must not include a GL header of its own.
#include <emscripten.h>
#include <glad/gl.h>
#include <imgui.h>
#include <imgui_internal.h>  // the hovered window, which a finger's swipe scrolls

#include <cmath>
#include <string>
#include <vector>

#include "app/viewer/frame_loop.h"
#include "app/viewer/viewer.h"
#include "platform/glfw_window.h"

namespace wobble {

// The browser's clock (s).
double seconds_now();
// The screen's device pixels per CSS pixel (2 on most laptops and phones, 1 on an ordinary
// monitor; the browser's zoom changes it too), within what is worth drawing.
float page_pixel_ratio();
// Whether the page asks for another drawing buffer size at pixel ratio `ratio`.
bool page_size_changed(const GlfwWindow& window, float ratio);
// The canvas fills the page (index.html's style sheet); its drawing buffer follows that size in
// device pixels, so that a high-DPI screen shows it sharp. The window's units are then device
// pixels too (emscripten's GLFW scales the mouse to the drawing buffer), and the panel is drawn
// `ratio` times larger, so it keeps its size on the screen.
void follow_page_size(GlfwWindow& window, float ratio);

// The page as draw_frame's host: emscripten's GLFW for input, the browser's clock, and the canvas
// the browser shows once the frame returns (after the page's figures for its tests are set).
class PageHost : public GlfwFrameHost {
 public:
  PageHost(GlfwWindow& window, ImGuiSession& ui) : window_(window), ui_(ui) {}
  PolledInput poll(const Viewer& /*viewer*/, const FrameMeters& /*meters*/) override {
    // The pixel ratio changes with the browser's zoom, or a window moved to another screen.
    ui_.rescale(page_pixel_ratio());
    follow_page_size(window_, ui_.scale());
    PolledInput input;
    std::vector<InputEvent>& events = input.events;
    events = window_.poll_events();
    scroll_under_finger();
    // The wheel, read by on_wheel from the browser's own event, in notches: to the camera and
    // to ImGui's panel (before its new frame) alike.
    for (const double notches : wheel_) {
      InputEvent event;
      event.type = InputEvent::Type::scroll;
      event.y = notches;
      events.push_back(event);
      ImGui::GetIO().MouseWheel += static_cast<float>(notches);
    }
    wheel_.clear();
    if (pinch_notches_ != 0.0) {
      InputEvent event;
      event.type = InputEvent::Type::scroll;
      event.y = pinch_notches_;
      events.push_back(event);
      pinch_notches_ = 0.0;
    }
    input.dropped_paths = take_dropped_paths();
    return input;
  }
  // Whether anything waits that poll would take: input, a wheel's notches, a pinch or swipe, files
  // opened, or a page of another size or pixel ratio.
  bool input_waiting() const {
    return window_.input_waiting() || !wheel_.empty() || pinch_notches_ != 0.0 ||
           panel_swipe_ != 0.0f || page_pixel_ratio() != ui_.scale() ||
           page_size_changed(window_, ui_.scale()) ||
           EM_ASM_INT({
             return typeof Module.wobbleOpenedWaiting == 'function' && Module.wobbleOpenedWaiting()
                        ? 1
                        : 0;
           }) != 0;
  }
  void wheel(double notches) {
    if (notches != 0.0) wheel_.push_back(notches);
  }
  // A finger's swipe on the panel, `pixels` (CSS) up: its list scrolls as far, under the finger.
  void swipe_panel(double pixels) {
    if (std::isfinite(pixels)) panel_swipe_ += static_cast<float>(pixels) * scale();
  }
  // Two fingers' spread grown `ratio` times: the camera that much nearer, as the wheel zooms
  // (1.15 times a notch, ViewCamera), but not over the panel.
  void pinch(double ratio) {
    if (std::isfinite(ratio) && ratio > 0.0) pinch_notches_ += std::log(ratio) / std::log(1.15);
  }
  // The files dropped onto the page or chosen with "Open file..." (index.html writes them into
  // the page's file system), and any emscripten's GLFW took.
  std::vector<std::string> take_dropped_paths() {
    std::vector<std::string> paths = window_.take_dropped_paths();
    const std::string opened = emscripten_run_script_string(
        "typeof Module.wobbleTakeOpened == 'function' ? Module.wobbleTakeOpened() : ''");
    std::size_t start = 0;
    while (start < opened.size()) {
      std::size_t end = opened.find('\n', start);
      if (end == std::string::npos) end = opened.size();
      if (end > start) paths.push_back(opened.substr(start, end - start));
      start = end + 1;
    }
    return paths;
  }
  float scale() const { return ui_.scale(); }
  double now() const override { return seconds_now(); }
  FrameSizes sizes() override {
    window_.window_size(width_, height_);
    FrameSizes sizes;
    sizes.width = width_;
    sizes.height = height_;
    sizes.window = Eigen::Vector2f(static_cast<float>(width_), static_cast<float>(height_));
    // The window's units are device pixels here: marks are scaled by the device pixel ratio.
    sizes.mark_scale = ui_.scale();
    return sizes;
  }
  // The PNG button (and F12) read the canvas before the browser shows it (GlfwFrameHost), as
  // the window reads its back buffer; the file is then offered as a download (offer_download).
  void present(const std::string& title) override {
    if (title != title_) window_.set_title(title_ = title);
  }
  // For the page and its tests (tests/web/page_check.py), once a frame is drawn: frames drawn,
  // the steps they show, the camera, the scene, the notices and the panel.
  void report(Viewer& viewer) {
    ++frames_drawn_;
    EM_ASM(
        {
          Module.wobbleFrames = $0;
          Module.wobbleSteps = $1;
        },
        frames_drawn_, static_cast<double>(viewer.session().shown_steps()));
    EM_ASM(
        {
          Module.wobbleCameraDistance = $0;
          Module.wobbleCameraYaw = $1;
          Module.wobbleUiScale = $2;
          Module.wobbleScene = UTF8ToString($3);
          Module.wobblePanelOpen = $4;
        },
        static_cast<double>(viewer.drawing().camera().distance),
        static_cast<double>(viewer.drawing().camera().yaw), static_cast<double>(scale()),
        viewer.session().scene().name.c_str(), viewer.panel().open() ? 1 : 0);
    // The notices on screen, one a line, as the user reads them over the view.
    std::string shown;
    for (const std::string& notice : viewer.files().notices().shown(notice_clock()))
      shown += (shown.empty() ? "" : "\n") + notice;
    EM_ASM({ Module.wobbleNotices = UTF8ToString($0); }, shown.c_str());
    // Where the open panel is, in CSS pixels, for index.html's fingers (null while folded).
    const PanelPlace place = viewer.panel().open() ? viewer.panel().place() : PanelPlace();
    EM_ASM(
        {
          Module.wobblePanelRect = $0 ? Array($1, $2, $3, $4) : null;
          Module.wobblePanelScroll = $5;
        },
        place.shown ? 1 : 0, place.x / scale(), place.y / scale(), place.width / scale(),
        place.height / scale(), static_cast<double>(panel_list_scroll()));
  }
  long frames_drawn() const { return frames_drawn_; }
  // How far the window under the pointer that scrolls is scrolled (window units), for the tests.
  static float panel_list_scroll() {
    ImGuiWindow* window = ImGui::GetCurrentContext()->HoveredWindow;
    while (window != nullptr && window->ScrollMax.y <= 0.0f)
      window = window->ParentWindow;
    return window != nullptr ? window->Scroll.y : 0.0f;
  }

 private:
  // The swipe since the last frame, to the window under the finger (the panel's list, or the
  // panel), before ImGui's new frame; the first that scrolls, from the innermost out.
  void scroll_under_finger() {
    if (panel_swipe_ == 0.0f) return;
    ImGuiWindow* window = ImGui::GetCurrentContext()->HoveredWindow;
    while (window != nullptr && window->ScrollMax.y <= 0.0f)
      window = window->ParentWindow;
    if (window != nullptr) ImGui::SetScrollY(window, window->Scroll.y + panel_swipe_);
    panel_swipe_ = 0.0f;
  }

  GlfwWindow& window_;
  ImGuiSession& ui_;
  double pinch_notches_ = 0.0;
  float panel_swipe_ = 0.0f;  // window units
  std::string title_;
  long frames_drawn_ = 0;
  std::vector<double> wheel_;  // notches since the last poll
};

}  // namespace wobble

#endif

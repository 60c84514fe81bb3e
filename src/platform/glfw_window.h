#ifndef WOBBLE_PLATFORM_GLFW_WINDOW_H
#define WOBBLE_PLATFORM_GLFW_WINDOW_H

#include <string>
#include <vector>

#include "context_error.h"
#include "input_event.h"

struct GLFWwindow;

namespace wobble {

// The windowed mode's context: a resizable GLFW window with a GL 3.3 core context, current and
// loaded through glad. Only context creation and input live here; drawing is the renderer's.
class GlfwWindow {
 public:
  // Opens the window. Throws ContextError with a one-line message (no display, no GL 3.3).
  GlfwWindow(int width, int height, const std::string& title);
  ~GlfwWindow();
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  GLFWwindow* handle() const { return window_; }
  bool should_close() const;
  void request_close();
  void set_title(const std::string& title);
  // Take the events that are waiting (or, with `wait_seconds` > 0, wait up to that long for one
  // to arrive), then hand over what arrived since the last call.
  std::vector<InputEvent> poll_events(double wait_seconds = 0.0);
  // Wait until input arrives (an event, or a file dropped) or `seconds` passed, whichever comes
  // first, not woken by wake(): pacing frames where the display does not pace the swaps.
  std::vector<InputEvent> wait_for_input(double seconds);
  // Wake a poll_events that waits. Safe from any thread while the window exists.
  static void wake();
  // Paths of the files dropped on the window since the last call, in the order dropped.
  std::vector<std::string> take_dropped_paths();
  // Whether events or dropped files wait for the next poll_events or take_dropped_paths (those
  // the window system has already handed over: the page's are, as they happen).
  bool input_waiting() const { return !events_.empty() || !dropped_.empty(); }
  void window_size(int& width, int& height) const;       // in window coordinates
  void framebuffer_size(int& width, int& height) const;  // in pixels
  float content_scale() const;  // 1 on ordinary screens, 2 on most high-DPI ones
  void swap_buffers();
  // Samples per pixel of the window's framebuffer: 4, or 0 on a software renderer.
  int samples() const { return samples_; }

 private:
  // Create the window and make its context current, with `samples` per pixel.
  void open(int width, int height, const std::string& title, int samples);
  // Whether the current context draws on the CPU (Mesa's llvmpipe and its kin).
  static bool software_renderer();

  GLFWwindow* window_ = nullptr;
  int samples_ = 0;
  std::vector<InputEvent> events_;
  std::vector<std::string> dropped_;
  double cursor_x_ = 0.0, cursor_y_ = 0.0;  // as of the last event handled
  friend struct GlfwCallbacks;
};

}  // namespace wobble

#endif

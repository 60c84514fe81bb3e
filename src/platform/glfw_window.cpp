#include "glfw_window.h"

#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <string>

namespace wobble {

namespace {

std::string last_glfw_error;

void remember_error(int, const char* description) {
  last_glfw_error = description;
}

GlfwWindow& owner(GLFWwindow* window) {
  return *static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window));
}

}  // namespace

// The callbacks are installed before ImGui's backend, which chains to them, so every event
// reaches both; the app decides from io.WantCaptureMouse who acts on it.
struct GlfwCallbacks {
  static void push(GLFWwindow* window, InputEvent event, int mods) {
    event.control = (mods & GLFW_MOD_CONTROL) != 0;
    event.shift = (mods & GLFW_MOD_SHIFT) != 0;
    event.alt = (mods & GLFW_MOD_ALT) != 0;
    owner(window).events_.push_back(event);
  }
  static void key(GLFWwindow* window, int key, int, int action, int mods) {
    if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
    InputEvent event;
    event.type = InputEvent::Type::key_press;
    event.code = key;
    // Cmd on a Mac is what Ctrl is elsewhere: Cmd+S saves the scene (in the page too, which keeps
    // the key from the browser), and Cmd+O is not O, the scene's opening view.
    push(window, event, (mods & GLFW_MOD_SUPER) != 0 ? mods | GLFW_MOD_CONTROL : mods);
  }
  static void button(GLFWwindow* window, int button, int action, int mods) {
    InputEvent event;
    event.type =
        action == GLFW_PRESS ? InputEvent::Type::button_press : InputEvent::Type::button_release;
    event.code = button;
    // Where the cursor was when the button went down: the last motion event, not
    // glfwGetCursorPos, which asks the X server for where the pointer is now, after any motion
    // still queued behind this event.
    event.x = owner(window).cursor_x_;
    event.y = owner(window).cursor_y_;
    push(window, event, mods);
  }
  static void cursor(GLFWwindow* window, double x, double y) {
    owner(window).cursor_x_ = x;
    owner(window).cursor_y_ = y;
    InputEvent event;
    event.type = InputEvent::Type::cursor_move;
    event.x = x;
    event.y = y;
    push(window, event, 0);
  }
  static void drop(GLFWwindow* window, int count, const char** paths) {
    for (int i = 0; i < count; ++i)
      owner(window).dropped_.emplace_back(paths[i]);
  }
  static void scroll(GLFWwindow* window, double dx, double dy) {
    InputEvent event;
    event.type = InputEvent::Type::scroll;
    event.x = dx;
    event.y = dy;
    push(window, event, 0);
  }
};

void GlfwWindow::open(int width, int height, const std::string& title, int samples) {
  glfwWindowHint(GLFW_SAMPLES, samples);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (window_ == nullptr) {
    glfwTerminate();
    throw ContextError("cannot create a window with OpenGL 3.3 core (GLFW: " + last_glfw_error +
                       "); try --headless");
  }
  glfwSetWindowUserPointer(window_, this);
  glfwGetCursorPos(window_, &cursor_x_, &cursor_y_);
  glfwMakeContextCurrent(window_);
  if (gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress)) == 0) {
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw ContextError("cannot load the OpenGL 3.3 functions of this window's context");
  }
  samples_ = samples;
}

bool GlfwWindow::software_renderer() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (renderer == nullptr) return false;
  const std::string name(renderer);
  for (const char* software : {"llvmpipe", "softpipe", "swrast", "Software Rasterizer"}) {
    if (name.find(software) != std::string::npos) return true;
  }
  return false;
}

GlfwWindow::GlfwWindow(int width, int height, const std::string& title) {
  glfwSetErrorCallback(remember_error);
  if (glfwInit() != GLFW_TRUE) {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((display == nullptr || *display == '\0') && (wayland == nullptr || *wayland == '\0')) {
      throw ContextError(
          "cannot open a window: no display (DISPLAY is not set); add --headless to render "
          "without one, or run under xvfb-run -a");
    }
    throw ContextError("cannot open a window (GLFW: " + last_glfw_error +
                       "); add --headless to render without a display, or run under xvfb-run -a");
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);  // the same size in inches on high-DPI
  // Hidden until its context is known: a software renderer (Mesa's llvmpipe, as under Xvfb or
  // on a machine without a GPU) gets a window without multisampling, since 4× MSAA doubled its
  // frame time there (large_cloth: 49 → 25 ms a frame under Xvfb beside the steps); a GPU keeps
  // the smooth edges. So the window is made once, or twice on a software renderer.
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  open(width, height, title, 4);
  if (software_renderer()) {
    glfwDestroyWindow(window_);
    open(width, height, title, 0);
  }
  glfwShowWindow(window_);
  glfwSwapInterval(1);  // follow the display: no tearing, no spinning faster than it shows
  glfwSetKeyCallback(window_, GlfwCallbacks::key);
  glfwSetMouseButtonCallback(window_, GlfwCallbacks::button);
  glfwSetCursorPosCallback(window_, GlfwCallbacks::cursor);
  glfwSetScrollCallback(window_, GlfwCallbacks::scroll);
  glfwSetDropCallback(window_, GlfwCallbacks::drop);
}

GlfwWindow::~GlfwWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool GlfwWindow::should_close() const {
  return glfwWindowShouldClose(window_) == GLFW_TRUE;
}

void GlfwWindow::request_close() {
  glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

void GlfwWindow::set_title(const std::string& title) {
  glfwSetWindowTitle(window_, title.c_str());
}

std::vector<InputEvent> GlfwWindow::poll_events(double wait_seconds) {
  if (wait_seconds > 0.0) {
    glfwWaitEventsTimeout(wait_seconds);
  } else {
    glfwPollEvents();
  }
  std::vector<InputEvent> events;
  events.swap(events_);
  return events;
}

std::vector<InputEvent> GlfwWindow::wait_for_input(double seconds) {
  const double until = glfwGetTime() + seconds;
  for (double left = seconds; left > 0.0 && events_.empty() && dropped_.empty();
       left = until - glfwGetTime()) {
    glfwWaitEventsTimeout(left);
  }
  std::vector<InputEvent> events;
  events.swap(events_);
  return events;
}

void GlfwWindow::wake() {
  glfwPostEmptyEvent();
}

std::vector<std::string> GlfwWindow::take_dropped_paths() {
  std::vector<std::string> paths;
  paths.swap(dropped_);
  return paths;
}

void GlfwWindow::window_size(int& width, int& height) const {
  glfwGetWindowSize(window_, &width, &height);
}

void GlfwWindow::framebuffer_size(int& width, int& height) const {
  glfwGetFramebufferSize(window_, &width, &height);
}

float GlfwWindow::content_scale() const {
  float x = 1.0f, y = 1.0f;
  glfwGetWindowContentScale(window_, &x, &y);
  return x > 0.0f ? x : 1.0f;
}

void GlfwWindow::swap_buffers() {
  glfwSwapBuffers(window_);
}

}  // namespace wobble

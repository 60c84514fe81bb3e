#include "app/web/page_host.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <emscripten/html5.h>

#include <algorithm>
#include <cmath>

namespace wobble {

namespace {

struct PageSize {
  int width = 0, height = 0;
};

// The drawing buffer's size the page asks for at pixel ratio `ratio`, or 0 x 0 before the canvas
// has one.
PageSize wanted_page_size(float ratio) {
  double css_width = 0.0, css_height = 0.0;
  emscripten_get_element_css_size("#canvas", &css_width, &css_height);
  return {static_cast<int>(std::lround(css_width * ratio)),
          static_cast<int>(std::lround(css_height * ratio))};
}

// Whether the drawing buffer must change to `wanted`.
bool differs_from(const GlfwWindow& window, PageSize wanted) {
  int width = 0, height = 0;
  window.window_size(width, height);
  return wanted.width > 0 && wanted.height > 0 &&
         (wanted.width != width || wanted.height != height);
}

}  // namespace

double seconds_now() {
  return 1e-3 * emscripten_get_now();
}

float page_pixel_ratio() {
  const double ratio = emscripten_get_device_pixel_ratio();
  return static_cast<float>(std::isfinite(ratio) ? std::clamp(ratio, 0.5, 4.0) : 1.0);
}

bool page_size_changed(const GlfwWindow& window, float ratio) {
  return differs_from(window, wanted_page_size(ratio));
}

void follow_page_size(GlfwWindow& window, float ratio) {
  const PageSize wanted = wanted_page_size(ratio);
  if (differs_from(window, wanted)) glfwSetWindowSize(window.handle(), wanted.width, wanted.height);
}

}  // namespace wobble

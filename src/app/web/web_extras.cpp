// What the desktop's C library and GLFW 3.3 have and emscripten's (3.1.6) lack, for the browser
// build only (declared in web_compat.h where the shared sources need a declaration).
#include <GLFW/glfw3.h>

#include <cerrno>

extern "C" {

// The page's canvas keeps CSS pixels as its window units: a scale of 1 (ImGui's sizes as on an
// ordinary desktop screen).
void glfwGetWindowContentScale(GLFWwindow*, float* x_scale, float* y_scale) {
  if (x_scale != nullptr) *x_scale = 1.0f;
  if (y_scale != nullptr) *y_scale = 1.0f;
}

// A page starts no process, so the student's step server (app/student/) never runs there: the
// call that would set up its child fails, as on a system without prctl.
int prctl(int, ...) {
  errno = ENOSYS;
  return -1;
}

}  // extern "C"

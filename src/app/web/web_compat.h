// Included before every C++ file of the browser build (-include, cmake/web_dependencies.cmake),
// never in the desktop build: what emscripten 3.1.6 (Debian 12) lacks of what the desktop's
// compiler and GLFW 3.3 give, so that the shared sources build unchanged.
//
// 1. Its libc++ (LLVM 14) declares std::to_chars and std::from_chars for floating point as
//    deleted. The calls of the shared sources are sent, by name, to the functions below: the
//    integer forms go on to the library's own, the floating-point forms keep the library's
//    meaning (to_chars: the shortest text that reads back to the same value; from_chars: no
//    leading blank or '+', out of range is std::errc::result_out_of_range).
// 2. Its GLFW is 3.2: no GLFW_SCALE_TO_MONITOR hint (ignored there) and no
//    glfwGetWindowContentScale (glfw_web_extras.cpp).
#ifndef WOBBLE_APP_WEB_WEB_COMPAT_H
#define WOBBLE_APP_WEB_WEB_COMPAT_H

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>
#include <type_traits>

namespace std {

template <typename T>
to_chars_result wobble_to_chars(char* first, char* last, T value) {
  if constexpr (is_floating_point_v<T>) {
    char text[64];
    int length = 0;
    for (int digits = 1; digits <= 17; ++digits) {
      length = snprintf(text, sizeof text, "%.*g", digits, static_cast<double>(value));
      if (!isfinite(value) || static_cast<T>(strtod(text, nullptr)) == value) break;
    }
    if (length > last - first) return {last, errc::value_too_large};
    memcpy(first, text, static_cast<size_t>(length));
    return {first + length, errc()};
  } else {
    return to_chars(first, last, value);
  }
}

template <typename T>
from_chars_result wobble_from_chars(const char* first, const char* last, T& value) {
  if constexpr (is_floating_point_v<T>) {
    if (first == last || *first == '+' || *first == ' ' || (*first >= '\t' && *first <= '\r')) {
      return {first, errc::invalid_argument};
    }
    const string text(first, last);
    char* stop = nullptr;
    errno = 0;
    const double parsed = strtod(text.c_str(), &stop);
    if (stop == text.c_str()) return {first, errc::invalid_argument};
    const char* end = first + (stop - text.c_str());
    if (errno == ERANGE && (parsed == HUGE_VAL || parsed == -HUGE_VAL)) {
      return {end, errc::result_out_of_range};
    }
    value = static_cast<T>(parsed);
    return {end, errc()};
  } else {
    return from_chars(first, last, value);
  }
}

}  // namespace std

#define to_chars wobble_to_chars
#define from_chars wobble_from_chars

struct GLFWwindow;
extern "C" void glfwGetWindowContentScale(GLFWwindow* window, float* x_scale, float* y_scale);
#ifndef GLFW_SCALE_TO_MONITOR
#define GLFW_SCALE_TO_MONITOR 0x0002200C
#endif

#endif

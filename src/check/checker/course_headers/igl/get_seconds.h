#ifndef WOBBLE_CHECK_COURSE_HEADERS_IGL_GET_SECONDS_H
#define WOBBLE_CHECK_COURSE_HEADERS_IGL_GET_SECONDS_H

// The checker's own stand-in for libigl's <igl/get_seconds.h>, which the course's main.cpp uses
// for its wind: seconds since some fixed moment, from a steady clock.

#include <chrono>

namespace igl {

inline double get_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace igl

#endif

#ifndef WOBBLE_CHECK_COURSE_HEADERS_IGL_PI_H
#define WOBBLE_CHECK_COURSE_HEADERS_IGL_PI_H

// The checker's own stand-in for libigl's <igl/PI.h>: π as a double constant.

namespace igl {

const double PI = 3.1415926535897932384626433832795;

}  // namespace igl

#endif

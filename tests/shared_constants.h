#ifndef WOBBLE_TESTS_SHARED_CONSTANTS_H
#define WOBBLE_TESTS_SHARED_CONSTANTS_H

// What many test files name alike, defined once: the test programs are compiled as unity builds
// (several files in one translation unit), where two files' own definitions would collide.
#include <Eigen/Core>
#include <string>

namespace wobble::testing {

// The shipped assets/ folder (WOBBLE_ASSETS_DIR, given by tests/CMakeLists.txt).
inline const std::string assets = WOBBLE_ASSETS_DIR;
// The window the viewer tests feed their mouse events in (pixels).
inline const Eigen::Vector2f window(1280.0f, 720.0f);

}  // namespace wobble::testing

#endif

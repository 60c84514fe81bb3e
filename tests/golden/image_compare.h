#ifndef WOBBLE_TESTS_GOLDEN_IMAGE_COMPARE_H
#define WOBBLE_TESTS_GOLDEN_IMAGE_COMPARE_H

#include <string>

#include "io/png_image.h"

namespace wobble::testing {

// When two renders count as the same picture. A pixel differs when any of its R, G, B channels
// differs by more than `channel`; the images match when the pixels that differ are at most
// `share` of all of them.
struct Tolerance {
  int channel = 0;
  double share = 0.0;
};

struct Comparison {
  bool same_size = false;
  long differing = 0;  // pixels beyond the channel threshold
  long total = 0;
  int largest = 0;  // largest channel difference anywhere
  double share() const { return total == 0 ? 1.0 : static_cast<double>(differing) / total; }
  bool matches(const Tolerance& tolerance) const { return same_size && share() <= tolerance.share; }
  // "1234 of 76800 pixels (1.61%) differ by more than 24; largest difference 255".
  std::string summary(const Tolerance& tolerance) const;
};

Comparison compare_images(const RgbaImage& expected, const RgbaImage& actual,
                          const Tolerance& tolerance);

// The expected image dimmed to grey, with the pixels that differ painted red: where to look.
// Empty when the sizes differ.
RgbaImage difference_image(const RgbaImage& expected, const RgbaImage& actual,
                           const Tolerance& tolerance);

}  // namespace wobble::testing

#endif

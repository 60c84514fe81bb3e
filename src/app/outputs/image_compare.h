#ifndef WOBBLE_APP_OUTPUTS_IMAGE_COMPARE_H
#define WOBBLE_APP_OUTPUTS_IMAGE_COMPARE_H

#include <string>

#include "io/png_image.h"

namespace wobble {

// When two renders count as the same picture: what `--expect` and the golden tests ask.
//
// Another GPU or driver draws the same scene with its edges a little differently: other sample
// positions and rounding put a silhouette, a grid line or a pin mark's edge a pixel over, or mix
// its two colours otherwise. A real change (the camera turned, the cloth sagging elsewhere, a
// spring missing, other lighting) gives colours that are nowhere near. So a pixel counts as
// differing only when its colour in one image appears nowhere within one pixel of the same place
// in the other image (each channel within `channel` levels), in either direction: expected
// against drawn, and drawn against expected, so that a thin line that vanished counts as much as
// one that appeared. An edge moved by one pixel then costs nothing, one moved by two a column of
// pixels. The images match when the pixels that differ are at most `share` of all.
struct ImageTolerance {
  int channel = 8;        // levels of 255 a channel may be off without counting
  double share = 0.0003;  // of the pixels that may differ (0.03%: 23 at 320 × 240)
};

struct ImageComparison {
  bool same_size = false;
  int expected_width = 0, expected_height = 0, actual_width = 0, actual_height = 0;
  long differing = 0;  // pixels that differ, as above
  long total = 0;
  // The largest channel difference between the two images at one pixel, among the pixels that
  // differ (among all when none does), and where it is (x right, y down from the top left).
  int largest = 0;
  int largest_x = 0, largest_y = 0;
  double share() const { return total == 0 ? 1.0 : static_cast<double>(differing) / total; }
  bool matches(const ImageTolerance& tolerance) const {
    return same_size && share() <= tolerance.share;
  }
  // "1234 of 76800 pixels (1.607%) differ by more than 8 beyond anti-aliasing (allowed: 0.030%);
  // largest difference 237 at (120, 45)", or the two sizes.
  std::string summary(const ImageTolerance& tolerance) const;
};

ImageComparison compare_images(const RgbaImage& expected, const RgbaImage& actual,
                               const ImageTolerance& tolerance);

// The expected image dimmed to grey, with the pixels that differ painted red: where to look.
// Empty when the sizes differ.
RgbaImage difference_image(const RgbaImage& expected, const RgbaImage& actual,
                           const ImageTolerance& tolerance);

}  // namespace wobble

#endif

#include "image_compare.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace wobble::testing {

namespace {

int pixel_difference(const unsigned char* a, const unsigned char* b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

}  // namespace

std::string Comparison::summary(const Tolerance& tolerance) const {
  if (!same_size) return "the images differ in size";
  char text[160];
  std::snprintf(text, sizeof text,
                "%ld of %ld pixels (%.3f%%) differ by more than %d (allowed: %.3f%%); largest "
                "difference %d",
                differing, total, 100.0 * share(), tolerance.channel, 100.0 * tolerance.share,
                largest);
  return text;
}

Comparison compare_images(const RgbaImage& expected, const RgbaImage& actual,
                          const Tolerance& tolerance) {
  Comparison comparison;
  comparison.same_size = expected.width == actual.width && expected.height == actual.height &&
                         expected.pixels.size() == actual.pixels.size();
  if (!comparison.same_size) return comparison;
  comparison.total = static_cast<long>(expected.width) * expected.height;
  for (long i = 0; i < comparison.total; ++i) {
    const int difference =
        pixel_difference(expected.pixels.data() + 4 * i, actual.pixels.data() + 4 * i);
    comparison.largest = std::max(comparison.largest, difference);
    if (difference > tolerance.channel) ++comparison.differing;
  }
  return comparison;
}

RgbaImage difference_image(const RgbaImage& expected, const RgbaImage& actual,
                           const Tolerance& tolerance) {
  RgbaImage diff;
  if (expected.width != actual.width || expected.height != actual.height) return diff;
  diff = expected;
  for (std::size_t i = 0; i + 3 < diff.pixels.size(); i += 4) {
    unsigned char* out = diff.pixels.data() + i;
    if (pixel_difference(expected.pixels.data() + i, actual.pixels.data() + i) >
        tolerance.channel) {
      out[0] = 255;
      out[1] = out[2] = 0;
    } else {
      const int grey = (out[0] + out[1] + out[2]) / 6;
      out[0] = out[1] = out[2] = static_cast<unsigned char>(grey);
    }
    out[3] = 255;
  }
  return diff;
}

}  // namespace wobble::testing

#include "app/outputs/image_compare.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace wobble {

namespace {

int pixel_difference(const unsigned char* a, const unsigned char* b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

// Whether some pixel of `image` within one pixel of (x, y) (the 3 by 3 there, cut at the
// border) has `colour`, each channel within `channel` levels.
bool explained_by(const unsigned char* colour, const RgbaImage& image, int x, int y, int channel) {
  for (int row = std::max(0, y - 1); row <= std::min(image.height - 1, y + 1); ++row) {
    for (int column = std::max(0, x - 1); column <= std::min(image.width - 1, x + 1); ++column) {
      if (pixel_difference(colour, image.pixel(column, row)) <= channel) return true;
    }
  }
  return false;
}

// Whether pixel (x, y) differs: its colour in either image beyond what the other shows around it.
bool differs(const RgbaImage& expected, const RgbaImage& actual, int x, int y, int channel) {
  const unsigned char* a = expected.pixel(x, y);
  const unsigned char* b = actual.pixel(x, y);
  if (pixel_difference(a, b) <= channel) return false;  // the common case, and the cheap one
  return !explained_by(a, actual, x, y, channel) || !explained_by(b, expected, x, y, channel);
}

}  // namespace

std::string ImageComparison::summary(const ImageTolerance& tolerance) const {
  char text[256];
  if (!same_size) {
    std::snprintf(text, sizeof text, "the images differ in size: expected %dx%d, drawn %dx%d",
                  expected_width, expected_height, actual_width, actual_height);
    return text;
  }
  std::snprintf(text, sizeof text,
                "%ld of %ld pixels (%.3f%%) differ by more than %d beyond anti-aliasing (allowed: "
                "%.3f%%); largest difference %d at (%d, %d)",
                differing, total, 100.0 * share(), tolerance.channel, 100.0 * tolerance.share,
                largest, largest_x, largest_y);
  return text;
}

ImageComparison compare_images(const RgbaImage& expected, const RgbaImage& actual,
                               const ImageTolerance& tolerance) {
  ImageComparison comparison;
  comparison.expected_width = expected.width;
  comparison.expected_height = expected.height;
  comparison.actual_width = actual.width;
  comparison.actual_height = actual.height;
  comparison.same_size = expected.width == actual.width && expected.height == actual.height &&
                         expected.pixels.size() == actual.pixels.size() &&
                         expected.pixels.size() == 4u * static_cast<std::size_t>(expected.width) *
                                                       static_cast<std::size_t>(expected.height);
  if (!comparison.same_size) return comparison;
  comparison.total = static_cast<long>(expected.width) * expected.height;
  int largest_anywhere = -1, anywhere_x = 0, anywhere_y = 0;
  comparison.largest = -1;
  for (int y = 0; y < expected.height; ++y) {
    for (int x = 0; x < expected.width; ++x) {
      const int difference = pixel_difference(expected.pixel(x, y), actual.pixel(x, y));
      if (difference > largest_anywhere) {
        largest_anywhere = difference;
        anywhere_x = x;
        anywhere_y = y;
      }
      if (!differs(expected, actual, x, y, tolerance.channel)) continue;
      ++comparison.differing;
      if (difference > comparison.largest) {
        comparison.largest = difference;
        comparison.largest_x = x;
        comparison.largest_y = y;
      }
    }
  }
  if (comparison.differing == 0) {
    comparison.largest = std::max(0, largest_anywhere);
    comparison.largest_x = anywhere_x;
    comparison.largest_y = anywhere_y;
  }
  return comparison;
}

RgbaImage difference_image(const RgbaImage& expected, const RgbaImage& actual,
                           const ImageTolerance& tolerance) {
  RgbaImage diff;
  if (expected.width != actual.width || expected.height != actual.height ||
      expected.pixels.size() != actual.pixels.size()) {
    return diff;
  }
  diff = expected;
  for (int y = 0; y < expected.height; ++y) {
    for (int x = 0; x < expected.width; ++x) {
      unsigned char* out = diff.pixels.data() + 4 * (static_cast<std::size_t>(y) * diff.width + x);
      if (differs(expected, actual, x, y, tolerance.channel)) {
        out[0] = 255;
        out[1] = out[2] = 0;
      } else {
        const int grey = (out[0] + out[1] + out[2]) / 6;
        out[0] = out[1] = out[2] = static_cast<unsigned char>(grey);
      }
      out[3] = 255;
    }
  }
  return diff;
}

}  // namespace wobble

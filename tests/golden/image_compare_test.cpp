#include "image_compare.h"

#include <gtest/gtest.h>

namespace {

using wobble::testing::Tolerance;

wobble::RgbaImage square_on_grey(int width, int height, int left, int top, int size) {
  wobble::RgbaImage image;
  image.width = width;
  image.height = height;
  image.pixels.assign(4 * width * height, 60);
  for (int y = top; y < top + size; ++y) {
    for (int x = left; x < left + size; ++x) {
      unsigned char* p = image.pixels.data() + 4 * (y * width + x);
      p[0] = 240;
      p[1] = 140;
      p[2] = 50;
    }
  }
  for (std::size_t i = 3; i < image.pixels.size(); i += 4)
    image.pixels[i] = 255;
  return image;
}

TEST(ImageCompare, IdenticalImagesMatchExactly) {
  const wobble::RgbaImage a = square_on_grey(100, 80, 20, 20, 30);
  const auto comparison = wobble::testing::compare_images(a, a, Tolerance{0, 0.0});
  EXPECT_TRUE(comparison.matches(Tolerance{0, 0.0}));
  EXPECT_EQ(comparison.differing, 0);
  EXPECT_EQ(comparison.largest, 0);
  EXPECT_EQ(comparison.total, 8000);
}

TEST(ImageCompare, SmallChannelNoiseIsWithinTheThreshold) {
  const wobble::RgbaImage a = square_on_grey(100, 80, 20, 20, 30);
  wobble::RgbaImage b = a;
  for (std::size_t i = 0; i < b.pixels.size(); i += 7)
    b.pixels[i] = static_cast<unsigned char>(b.pixels[i] + 10);
  const Tolerance tolerance{24, 0.002};
  const auto comparison = wobble::testing::compare_images(a, b, tolerance);
  EXPECT_EQ(comparison.differing, 0);
  EXPECT_EQ(comparison.largest, 10);
  EXPECT_TRUE(comparison.matches(tolerance));
}

TEST(ImageCompare, AShapeMovedByTwoPixelsFails) {
  const wobble::RgbaImage a = square_on_grey(100, 80, 20, 20, 30);
  const wobble::RgbaImage b = square_on_grey(100, 80, 22, 20, 30);
  const Tolerance tolerance{24, 0.002};
  const auto comparison = wobble::testing::compare_images(a, b, tolerance);
  EXPECT_EQ(comparison.differing, 2 * 2 * 30);  // a two-pixel strip appears and one vanishes
  EXPECT_FALSE(comparison.matches(tolerance)) << comparison.summary(tolerance);
}

TEST(ImageCompare, TheShareDecides) {
  const wobble::RgbaImage a = square_on_grey(100, 100, 0, 0, 0);
  wobble::RgbaImage b = a;
  for (int i = 0; i < 20; ++i)
    b.pixels[4 * (i * 37)] = 255;  // 20 of 10,000 pixels: 0.2%
  EXPECT_TRUE(
      wobble::testing::compare_images(a, b, Tolerance{24, 0.002}).matches(Tolerance{24, 0.002}));
  EXPECT_FALSE(
      wobble::testing::compare_images(a, b, Tolerance{24, 0.0019}).matches(Tolerance{24, 0.0019}));
}

TEST(ImageCompare, DifferentSizesNeverMatch) {
  const auto comparison = wobble::testing::compare_images(
      square_on_grey(10, 10, 0, 0, 1), square_on_grey(10, 11, 0, 0, 1), Tolerance{255, 1.0});
  EXPECT_FALSE(comparison.matches(Tolerance{255, 1.0}));
  EXPECT_TRUE(wobble::testing::difference_image(square_on_grey(10, 10, 0, 0, 1),
                                                square_on_grey(10, 11, 0, 0, 1), Tolerance{})
                  .pixels.empty());
}

TEST(ImageCompare, DifferenceImagePaintsDifferingPixelsRed) {
  const wobble::RgbaImage a = square_on_grey(10, 10, 0, 0, 0);
  wobble::RgbaImage b = a;
  b.pixels[4 * 55 + 1] = 200;
  const wobble::RgbaImage diff = wobble::testing::difference_image(a, b, Tolerance{24, 0.0});
  EXPECT_EQ(diff.pixel(5, 5)[0], 255);
  EXPECT_EQ(diff.pixel(5, 5)[1], 0);
  EXPECT_EQ(diff.pixel(4, 5)[0], diff.pixel(4, 5)[1]);  // the rest is grey
}

}  // namespace

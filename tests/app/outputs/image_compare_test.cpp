#include "app/outputs/image_compare.h"

#include <gtest/gtest.h>

#include <utility>

namespace {

using Tolerance = wobble::ImageTolerance;

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
  const auto comparison = wobble::compare_images(a, a, Tolerance{0, 0.0});
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
  const auto comparison = wobble::compare_images(a, b, tolerance);
  EXPECT_EQ(comparison.differing, 0);
  EXPECT_EQ(comparison.largest, 10);
  EXPECT_TRUE(comparison.matches(tolerance));
}

TEST(ImageCompare, AShapeMovedByTwoPixelsFails) {
  const wobble::RgbaImage a = square_on_grey(100, 80, 20, 20, 30);
  const wobble::RgbaImage b = square_on_grey(100, 80, 22, 20, 30);
  const Tolerance tolerance{24, 0.002};
  const auto comparison = wobble::compare_images(a, b, tolerance);
  // A two-pixel strip appears and one vanishes: all four columns count, the outer ones because
  // their colour is two pixels from where it was, the inner ones because the other image has
  // only the other colour around them; except the inner columns' end pixels, which have the
  // background above or below them in both images.
  EXPECT_EQ(comparison.differing, 2 * 2 * 30 - 4);
  EXPECT_FALSE(comparison.matches(tolerance)) << comparison.summary(tolerance);
}

TEST(ImageCompare, AShapeMovedByOnePixelMatchesExactly) {
  // Every edge of the square one pixel over, as another driver's rasterization may put it: each
  // pixel's colour is found within one pixel of the same place in the other image.
  const wobble::RgbaImage a = square_on_grey(100, 80, 20, 20, 30);
  for (const auto& [left, top] : {std::pair{21, 20}, std::pair{19, 21}, std::pair{21, 19}}) {
    const wobble::RgbaImage b = square_on_grey(100, 80, left, top, 30);
    const auto comparison = wobble::compare_images(a, b, Tolerance{8, 0.0});
    EXPECT_EQ(comparison.differing, 0) << comparison.summary(Tolerance{8, 0.0});
    EXPECT_TRUE(comparison.matches(Tolerance{8, 0.0}));
    EXPECT_EQ(comparison.largest, 180);  // 240 against 60: the plain difference is still shown
  }
}

TEST(ImageCompare, AnEdgePixelMixedOtherwiseMatchesWhenItsNeighbourHasThatMix) {
  // A one-pixel-wide anti-aliased border, half orange: another driver drew it a pixel over.
  wobble::RgbaImage a = square_on_grey(40, 40, 10, 10, 10);
  wobble::RgbaImage b = a;
  for (int y = 10; y < 20; ++y) {
    a.pixels[4 * (y * 40 + 20)] = 150;  // the mix just right of the square in a
    b.pixels[4 * (y * 40 + 21)] = 150;  // and one pixel further in b
  }
  EXPECT_EQ(wobble::compare_images(a, b, Tolerance{8, 0.0}).differing, 0);
}

TEST(ImageCompare, AThinLineThatVanishedCountsEveryPixel) {
  wobble::RgbaImage a = square_on_grey(50, 50, 0, 0, 0);
  const wobble::RgbaImage b = a;
  for (int x = 5; x < 45; ++x)
    a.pixels[4 * (25 * 50 + x)] = 200;  // a red-ish line one pixel thick, only in a
  const auto comparison = wobble::compare_images(a, b, Tolerance{8, 0.0});
  EXPECT_EQ(comparison.differing, 40);
  EXPECT_EQ(comparison.largest, 140);
  EXPECT_EQ(comparison.largest_y, 25);
  // And the other way round: a line that appeared.
  EXPECT_EQ(wobble::compare_images(b, a, Tolerance{8, 0.0}).differing, 40);
}

TEST(ImageCompare, TheShareDecides) {
  const wobble::RgbaImage a = square_on_grey(100, 100, 0, 0, 0);
  wobble::RgbaImage b = a;
  for (int i = 0; i < 20; ++i)
    b.pixels[4 * (i * 37)] = 255;  // 20 of 10,000 pixels: 0.2%
  EXPECT_TRUE(wobble::compare_images(a, b, Tolerance{24, 0.002}).matches(Tolerance{24, 0.002}));
  EXPECT_FALSE(wobble::compare_images(a, b, Tolerance{24, 0.0019}).matches(Tolerance{24, 0.0019}));
}

TEST(ImageCompare, DifferentSizesNeverMatch) {
  const auto comparison = wobble::compare_images(
      square_on_grey(10, 10, 0, 0, 1), square_on_grey(10, 11, 0, 0, 1), Tolerance{255, 1.0});
  EXPECT_FALSE(comparison.matches(Tolerance{255, 1.0}));
  EXPECT_TRUE(wobble::difference_image(square_on_grey(10, 10, 0, 0, 1),
                                       square_on_grey(10, 11, 0, 0, 1), Tolerance{})
                  .pixels.empty());
}

TEST(ImageCompare, DifferenceImagePaintsDifferingPixelsRed) {
  const wobble::RgbaImage a = square_on_grey(10, 10, 0, 0, 0);
  wobble::RgbaImage b = a;
  b.pixels[4 * 55 + 1] = 200;
  const wobble::RgbaImage diff = wobble::difference_image(a, b, Tolerance{24, 0.0});
  EXPECT_EQ(diff.pixel(5, 5)[0], 255);
  EXPECT_EQ(diff.pixel(5, 5)[1], 0);
  EXPECT_EQ(diff.pixel(4, 5)[0], diff.pixel(4, 5)[1]);  // the rest is grey
}

}  // namespace

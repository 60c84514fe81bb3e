#include "io/png_image.h"

#include <gtest/gtest.h>

#include <fstream>

#include "io/atomic_file.h"
#include "sim/input_error.h"
#include "temporary_folder.h"

namespace {

wobble::RgbaImage gradient(int width, int height) {
  wobble::RgbaImage image;
  image.width = width;
  image.height = height;
  image.pixels.resize(4 * static_cast<std::size_t>(width) * height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      unsigned char* pixel = image.pixels.data() + 4 * (y * width + x);
      pixel[0] = static_cast<unsigned char>(x * 7);
      pixel[1] = static_cast<unsigned char>(y * 13);
      pixel[2] = static_cast<unsigned char>(x ^ y);
      pixel[3] = 255;
    }
  }
  return image;
}

TEST(PngImage, WritesAndReadsBackTheSamePixels) {
  wobble::testing::TemporaryFolder folder;
  const wobble::RgbaImage image = gradient(37, 23);
  wobble::write_png(folder.file("a.png"), image);
  const wobble::RgbaImage back = wobble::read_png(folder.file("a.png"));
  EXPECT_EQ(back.width, 37);
  EXPECT_EQ(back.height, 23);
  EXPECT_EQ(back.pixels, image.pixels);
  EXPECT_EQ(back.pixel(5, 3)[0], 35);  // rows from the top, 4 bytes a pixel
  EXPECT_EQ(back.pixel(5, 3)[1], 39);
  EXPECT_EQ(folder.entries().size(), 1u) << "no temporary file left behind";
}

TEST(PngImage, EncodingIsDeterministic) {
  const wobble::RgbaImage image = gradient(64, 48);
  EXPECT_EQ(wobble::encode_png(image), wobble::encode_png(image));
  wobble::RgbaImage other = image;
  other.pixels[4 * 100] ^= 1;
  EXPECT_NE(wobble::encode_png(image), wobble::encode_png(other));
}

TEST(PngImage, RefusesAPixelCountThatDoesNotMatchTheSize) {
  wobble::RgbaImage image = gradient(4, 4);
  image.pixels.pop_back();
  EXPECT_THROW(wobble::encode_png(image), std::invalid_argument);
}

TEST(PngImage, ReadingANonImageNamesTheFile) {
  wobble::testing::TemporaryFolder folder;
  std::ofstream(folder.file("not.png")) << "hello";
  try {
    wobble::read_png(folder.file("not.png"));
    FAIL() << "expected InputError";
  } catch (const wobble::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("not.png"), std::string::npos) << error.what();
  }
  EXPECT_THROW(wobble::read_png(folder.file("missing.png")), wobble::InputError);
}

TEST(PngImage, WritingIntoAMissingFolderFailsCleanly) {
  wobble::testing::TemporaryFolder folder;
  EXPECT_THROW(wobble::write_png(folder.file("no/such/a.png"), gradient(2, 2)),
               wobble::OutputError);
}

}  // namespace

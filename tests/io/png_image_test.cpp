#include "io/png_image.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>

#include "io/atomic_file.h"
#include "io/input_file_limits.h"
#include "png_bytes.h"
#include "sim/input_error.h"
#include "temporary_folder.h"

namespace {

using wobble::testing::png_header;

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

TEST(PngImage, TextureProblemLooksAtTheHeaderOnly) {
  wobble::testing::TemporaryFolder folder;
  wobble::RgbaImage image;
  image.width = wobble::max_texture_side;
  image.height = 2;
  image.pixels.assign(4 * image.width * image.height, 128);
  wobble::write_png(folder.file("wide.png"), image);
  EXPECT_EQ(wobble::texture_problem(folder.file("wide.png")), "");

  // A header that promises 16384 x 16384 pixels (1 GiB as RGBA), with no pixels behind it.
  std::ofstream(folder.file("huge.png"), std::ios::binary) << png_header(16384, 16384);
  EXPECT_EQ(wobble::texture_problem(folder.file("huge.png")),
            "is 16384x16384 pixels, above Wobble's limit of " +
                std::to_string(wobble::max_texture_side) + " pixels a side");
  std::ofstream(folder.file("tall.png"), std::ios::binary)
      << png_header(1, wobble::max_texture_side + 1);
  EXPECT_NE(wobble::texture_problem(folder.file("tall.png")), "");

  std::ofstream(folder.file("text.png")) << "not an image";
  EXPECT_EQ(wobble::texture_problem(folder.file("text.png")).rfind("is not a readable image", 0),
            0u);
  EXPECT_EQ(wobble::texture_problem(folder.file("none.png")),
            "no such file, expected a PNG texture");
  ASSERT_EQ(mkfifo(folder.file("pipe.png").c_str(), 0600), 0);
  EXPECT_EQ(wobble::texture_problem(folder.file("pipe.png")),
            "is a FIFO (named pipe), not a regular file, expected a PNG texture");
}

TEST(PngImage, ReadPngRefusesAnImageAboveItsLimitBeforeDecoding) {
  wobble::testing::TemporaryFolder folder;
  std::ofstream(folder.file("huge.png"), std::ios::binary) << png_header(16384, 16384);
  try {
    wobble::read_png(folder.file("huge.png"), wobble::max_texture_side);
    ADD_FAILURE() << "decoded a 16384 x 16384 header";
  } catch (const wobble::InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              folder.file("huge.png") + ": is 16384x16384 pixels, above Wobble's limit of " +
                  std::to_string(wobble::max_texture_side) + " pixels a side");
  }
}

}  // namespace

// read_png on every kind of PNG the format allows, written by the tests' own encoder
// (png_bytes.h), against the RGBA each pixel must come out as.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/png_image.h"
#include "png_bytes.h"
#include "sim/input_error.h"
#include "temporary_folder.h"

namespace {

using namespace wobble::testing;

// A sample that varies with x, y and the channel, below 2^bit_depth.
std::uint16_t pattern(int x, int y, int channel, int bit_depth) {
  const unsigned value = 37u * x + 101u * y + 59u * channel + 7u * x * y;
  return static_cast<std::uint16_t>(value % (1u << bit_depth));
}

// A stored sample as 8 bits: low depths scale up to 0..255, 16-bit samples keep their high byte.
int to_8_bits(int sample, int bit_depth) {
  if (bit_depth == 16) return sample >> 8;
  return sample * 255 / ((1 << bit_depth) - 1);
}

PngSpec patterned(int width, int height, int bit_depth, int color, bool interlaced) {
  PngSpec spec;
  spec.width = width;
  spec.height = height;
  spec.bit_depth = bit_depth;
  spec.color = color;
  spec.interlaced = interlaced;
  const int channels = png_channels(color);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < channels; ++c)
        spec.samples.push_back(pattern(x, y, c, bit_depth));
  return spec;
}

// The RGBA that pixel (x, y) of `spec` must decode to.
std::array<int, 4> expected_rgba(const PngSpec& spec, int x, int y) {
  const int channels = png_channels(spec.color);
  const auto sample = [&](int c) { return spec.samples[(y * spec.width + x) * channels + c]; };
  const auto eight = [&](int c) { return to_8_bits(sample(c), spec.bit_depth); };
  switch (spec.color) {
    case grey: {
      int alpha = 255;
      if (spec.transparency.size() == 2) {
        const int key = (static_cast<unsigned char>(spec.transparency[0]) << 8) |
                        static_cast<unsigned char>(spec.transparency[1]);
        if (sample(0) == key) alpha = 0;
      }
      return {eight(0), eight(0), eight(0), alpha};
    }
    case grey_alpha:
      return {eight(0), eight(0), eight(0), eight(1)};
    case rgb:
      return {eight(0), eight(1), eight(2), 255};
    case palette: {
      const int index = sample(0);
      const int alpha = index < static_cast<int>(spec.transparency.size())
                            ? static_cast<unsigned char>(spec.transparency[index])
                            : 255;
      return {spec.palette[3 * index], spec.palette[3 * index + 1], spec.palette[3 * index + 2],
              alpha};
    }
    default:
      return {eight(0), eight(1), eight(2), eight(3)};
  }
}

void expect_decodes(const PngSpec& spec, const std::string& label) {
  TemporaryFolder folder;
  const std::string path = folder.file("t.png");
  std::ofstream(path, std::ios::binary) << encode_test_png(spec);
  const wobble::RgbaImage image = wobble::read_png(path);
  ASSERT_EQ(image.width, spec.width) << label;
  ASSERT_EQ(image.height, spec.height) << label;
  int wrong = 0;
  for (int y = 0; y < spec.height; ++y) {
    for (int x = 0; x < spec.width; ++x) {
      const std::array<int, 4> want = expected_rgba(spec, x, y);
      for (int c = 0; c < 4; ++c) {
        if (image.pixel(x, y)[c] != want[c] && wrong++ < 3) {
          ADD_FAILURE() << label << ": pixel (" << x << ", " << y << ") channel " << c << " is "
                        << int(image.pixel(x, y)[c]) << ", expected " << want[c];
        }
      }
    }
  }
  EXPECT_EQ(wrong, 0) << label;
}

std::string describe(int bit_depth, int color, bool interlaced) {
  return std::to_string(bit_depth) + "-bit colour type " + std::to_string(color) +
         (interlaced ? " interlaced" : "");
}

TEST(PngFormats, GreyAtEveryBitDepthAndInterlacing) {
  // 13 x 11 is no multiple of 8, so packed rows end part-way through a byte and every Adam7
  // pass is partly empty.
  for (const bool interlaced : {false, true})
    for (const int depth : {1, 2, 4, 8, 16})
      expect_decodes(patterned(13, 11, depth, grey, interlaced), describe(depth, grey, interlaced));
}

TEST(PngFormats, ColourAndAlphaAtEightAndSixteenBits) {
  for (const bool interlaced : {false, true})
    for (const int depth : {8, 16})
      for (const int color : {rgb, grey_alpha, rgba})
        expect_decodes(patterned(9, 7, depth, color, interlaced),
                       describe(depth, color, interlaced));
}

TEST(PngFormats, PalettesWithAndWithoutTransparency) {
  for (const bool interlaced : {false, true}) {
    for (const int depth : {1, 2, 4, 8}) {
      PngSpec spec = patterned(10, 6, depth, palette, interlaced);
      const int entries = 1 << depth;
      for (int i = 0; i < entries; ++i) {
        spec.palette.push_back(static_cast<std::uint8_t>(i * 53 + 1));
        spec.palette.push_back(static_cast<std::uint8_t>(255 - i * 31));
        spec.palette.push_back(static_cast<std::uint8_t>(i * 97));
      }
      expect_decodes(spec, describe(depth, palette, interlaced));
      // Alpha for the first entries only; the others stay opaque.
      for (int i = 0; i < std::max(1, entries / 2); ++i)
        spec.transparency.push_back(static_cast<char>(i * 40));
      expect_decodes(spec, describe(depth, palette, interlaced) + " with tRNS");
    }
  }
}

TEST(PngFormats, GreyTransparencyKey) {
  PngSpec spec = patterned(8, 8, 8, grey, false);
  spec.transparency = std::string("\0", 1) + static_cast<char>(spec.samples[3]);
  expect_decodes(spec, "grey with a tRNS key");
}

TEST(PngFormats, DamagedFilesAreRefusedWithTheFileNamed) {
  const std::string good = encode_test_png(patterned(16, 16, 8, rgba, false));
  TemporaryFolder folder;
  const std::string path = folder.file("bad.png");
  const auto refused = [&](const std::string& bytes, const std::string& label) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    try {
      wobble::read_png(path);
      ADD_FAILURE() << label << ": decoded";
    } catch (const wobble::InputError& error) {
      EXPECT_EQ(std::string(error.what()).rfind(path + ": is not a readable image (", 0), 0u)
          << label << ": " << error.what();
    }
  };
  // Cut inside the signature, the header, the pixel data and the zlib checksum that ends it.
  // (A file cut after that checksum still decodes: every pixel is there and checked.)
  for (const std::size_t keep :
       {std::size_t{5}, std::size_t{20}, good.size() / 2, good.size() - 18}) {
    refused(good.substr(0, keep), "truncated to " + std::to_string(keep) + " bytes");
  }
  std::string flipped = good;
  flipped[good.size() / 2] ^= 0x10;  // inside IDAT: the CRC no longer matches
  refused(flipped, "a flipped bit");
  std::string checksum = good;
  checksum[good.size() - 17] ^= 0x01;  // the last byte of the pixel data's Adler-32
  refused(checksum, "a wrong zlib checksum");
  refused("GIF89a" + good.substr(6), "another format's signature");
}

TEST(PngFormats, TextChunksAreBoundedAndOtherwiseIgnored) {
  PngSpec spec = patterned(6, 5, 8, rgba, false);
  const std::string good = encode_test_png(spec);
  const std::size_t after_header = 8 + 25;  // the signature and IHDR
  TemporaryFolder folder;
  const std::string path = folder.file("text.png");
  // Some text before the pixels, as editors write: read past.
  std::string with_text = good;
  with_text.insert(after_header, png_chunk("tEXt", std::string("Comment\0", 8) + "made by hand"));
  std::ofstream(path, std::ios::binary | std::ios::trunc) << with_text;
  EXPECT_EQ(wobble::read_png(path).width, 6);
  // Compressed text that would take 5 MB once inflated, in chunks under 1 MiB each: refused
  // at the 4 MiB the decoder may keep, not inflated.
  std::string bomb = good;
  for (int i = 0; i < 5; ++i) {
    bomb.insert(after_header, png_chunk("zTXt", "C" + std::to_string(i) + std::string("\0\0", 2) +
                                                    zlib_stored(std::string(1'000'000, 'a'))));
  }
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bomb;
  try {
    wobble::read_png(path);
    ADD_FAILURE() << "decoded a PNG with 5 MB of compressed text";
  } catch (const wobble::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("limits"), std::string::npos) << error.what();
  }
}

TEST(PngFormats, ReadsEveryImageWobbleWrites) {
  wobble::RgbaImage image;
  image.width = 300;  // 1,200 bytes a row: libspng chooses filters, unlike the test encoder
  image.height = 70;
  for (int i = 0; i < image.width * image.height * 4; ++i)
    image.pixels.push_back(static_cast<unsigned char>((i * 7) ^ (i / 1200)));
  TemporaryFolder folder;
  wobble::write_png(folder.file("w.png"), image);
  EXPECT_EQ(wobble::read_png(folder.file("w.png")).pixels, image.pixels);
}

// The fuzz harness's seeds (written by tests/fuzz/make_png_seeds.cpp) are what their names say,
// so the fuzzer starts from every kind of valid file and from files broken in known ways.
TEST(PngSeeds, EachSeedIsWhatItsNameSays) {
  int valid = 0, broken = 0;
  for (const auto& entry : std::filesystem::directory_iterator(WOBBLE_PNG_SEEDS_DIR)) {
    const std::string name = entry.path().filename().string();
    const bool should_decode = name.rfind("valid_", 0) == 0;
    ASSERT_TRUE(should_decode || name.rfind("broken_", 0) == 0) << name;
    try {
      const wobble::RgbaImage image = wobble::read_png(entry.path().string());
      EXPECT_TRUE(should_decode) << name << " decoded";
      EXPECT_GT(image.width, 0) << name;
      ++valid;
    } catch (const wobble::InputError& error) {
      EXPECT_FALSE(should_decode) << name << ": " << error.what();
      ++broken;
    }
  }
  EXPECT_GE(valid, 40);  // 1 to 16 bits, five colour types, tRNS, interlaced or not
  EXPECT_GE(broken, 7);
}

}  // namespace

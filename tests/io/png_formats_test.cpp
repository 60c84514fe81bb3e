// read_png on every kind of PNG the format allows, written by the tests' own encoder
// (png_bytes.h), against the RGBA each pixel must come out as.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

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

// The chunks of a PNG file after its signature, as (type, data).
std::vector<std::pair<std::string, std::string>> chunks_of(const std::string& png) {
  std::vector<std::pair<std::string, std::string>> chunks;
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::size_t length = (std::size_t(static_cast<unsigned char>(png[at])) << 24) |
                               (std::size_t(static_cast<unsigned char>(png[at + 1])) << 16) |
                               (std::size_t(static_cast<unsigned char>(png[at + 2])) << 8) |
                               std::size_t(static_cast<unsigned char>(png[at + 3]));
    chunks.emplace_back(png.substr(at + 4, 4), png.substr(at + 8, length));
    at += 12 + length;
  }
  return chunks;
}

// Every way a file can be damaged is refused by read_png and by texture_problem alike (a scene's
// texture is checked whole when the scene loads, drawn or not), on one line naming the file and,
// where a chunk is to blame, the chunk.
TEST(PngFormats, DamagedFilesAreRefusedWithTheFileNamed) {
  const std::string good = encode_test_png(patterned(16, 16, 8, rgba, false));
  const auto chunks = chunks_of(good);
  ASSERT_EQ(chunks.size(), 3u);  // IHDR, IDAT, IEND
  const std::string signature = good.substr(0, 8);
  const std::string ihdr = png_chunk("IHDR", chunks[0].second);
  const std::string& pixels = chunks[1].second;
  const std::string iend = png_chunk("IEND", "");
  const auto wrong_crc = [](std::string chunk) {
    chunk.back() ^= 0x01;
    return chunk;
  };
  std::string adler = pixels;
  adler.back() ^= 0x01;  // the last byte of the pixel data's Adler-32, with a CRC that matches
  const std::string damaged = "the PNG is damaged: ";
  const std::string unreadable = "is not a readable image (";
  const std::vector<std::pair<std::string, std::string>> cases = {
      // Cut inside the signature, the header, the pixel data and just before IEND.
      {good.substr(0, 5), unreadable},
      {good.substr(0, 20), damaged + "the file ends inside chunk IHDR"},
      {good.substr(0, good.size() / 2), damaged + "the file ends inside chunk IDAT"},
      {good.substr(0, good.size() - 18), damaged + "the file ends inside chunk IDAT"},
      {good.substr(0, good.size() - 12), damaged + "the file ends after chunk IDAT, without the "
                                                   "IEND chunk"},
      {good.substr(0, good.size() - 3), damaged + "the file ends inside chunk IEND"},
      {good.substr(0, 8), damaged + "the file ends after the PNG signature, without any chunk"},
      // A wrong CRC in every chunk, critical or ancillary, before or after the pixels.
      {signature + wrong_crc(ihdr) + png_chunk("IDAT", pixels) + iend,
       damaged + "chunk IHDR checksum is wrong"},
      {signature + ihdr + wrong_crc(png_chunk("IDAT", pixels)) + iend,
       damaged + "chunk IDAT checksum is wrong"},
      {signature + ihdr + png_chunk("IDAT", pixels.substr(0, 100)) +
           wrong_crc(png_chunk("IDAT", pixels.substr(100))) + iend,
       damaged + "chunk IDAT checksum is wrong"},
      {signature + ihdr + png_chunk("IDAT", pixels) + wrong_crc(iend),
       damaged + "chunk IEND checksum is wrong"},
      {signature + ihdr + wrong_crc(png_chunk("tEXt", std::string("a\0b", 3))) +
           png_chunk("IDAT", pixels) + iend,
       damaged + "chunk tEXt checksum is wrong"},
      {signature + ihdr + png_chunk("IDAT", pixels) +
           wrong_crc(png_chunk("tEXt", std::string("a\0b", 3))) + iend,
       damaged + "chunk tEXt checksum is wrong"},
      {signature + ihdr + wrong_crc(png_chunk("prVt", "xyz")) + png_chunk("IDAT", pixels) + iend,
       damaged + "chunk prVt checksum is wrong"},
      // A flipped bit in the pixel data breaks the zlib stream before libspng reads the CRC.
      {[&] {
         std::string flipped = good;
         flipped[good.size() / 2] ^= 0x10;
         return flipped;
       }(),
       damaged + "chunk IDAT checksum is wrong"},
      // What the chunks cannot show is left to libspng's own words.
      {signature + ihdr + png_chunk("IDAT", adler) + iend, unreadable},
      {signature + ihdr + png_chunk("IDAT", pixels.substr(0, pixels.size() / 2)) + iend,
       unreadable},
      {"GIF89a" + good.substr(6), unreadable},
  };
  TemporaryFolder folder;
  const std::string path = folder.file("bad.png");
  for (const auto& [bytes, expected] : cases) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    SCOPED_TRACE(expected + " (" + std::to_string(bytes.size()) + " bytes)");
    try {
      wobble::read_png(path);
      ADD_FAILURE() << "decoded";
    } catch (const wobble::InputError& error) {
      EXPECT_EQ(std::string(error.what()).rfind(path + ": " + expected, 0), 0u) << error.what();
      EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos);
    }
    EXPECT_EQ(wobble::texture_problem(path).rfind(expected, 0), 0u)
        << wobble::texture_problem(path);
  }
  // The good file, with bytes after IEND (which some programs leave), reads in both.
  std::ofstream(path, std::ios::binary | std::ios::trunc) << good + "trailing";
  EXPECT_EQ(wobble::texture_problem(path), "");
  EXPECT_EQ(wobble::read_png(path).width, 16);
}

// texture_problem decodes every pixel, row by row, of every kind of PNG read_png reads.
TEST(PngFormats, TextureProblemAcceptsWhatReadPngReads) {
  TemporaryFolder folder;
  const std::string path = folder.file("t.png");
  for (const int color : {grey, rgb, grey_alpha, rgba}) {
    for (const bool interlaced : {false, true}) {
      std::ofstream(path, std::ios::binary | std::ios::trunc)
          << encode_test_png(patterned(13, 7, 16, color, interlaced));
      EXPECT_EQ(wobble::texture_problem(path), "") << color << " " << interlaced;
      EXPECT_EQ(wobble::read_png(path).height, 7);
    }
  }
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

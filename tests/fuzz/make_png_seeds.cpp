// Writes the seeds of fuzz_png into the folder given: small PNGs of every bit depth (1 to 16),
// colour type (grey, grey and alpha, colour, colour and alpha, palette), with and without tRNS,
// interlaced and not, one that Wobble itself wrote (filtered and compressed), and broken ones
// (truncated, a wrong CRC or checksum, another signature, a header above the size limit).
// Names start with valid_ or broken_; PngSeeds.EachSeedIsWhatItsNameSays checks them.
//
//   build/tests/make_png_seeds tests/fuzz/corpus/fuzz_png
#include <fstream>
#include <iostream>
#include <string>

#include "io/png_bytes.h"
#include "io/png_image.h"

namespace {

using namespace wobble::testing;

PngSpec image(int bit_depth, int color, bool interlaced) {
  PngSpec spec;
  spec.width = 11;  // no multiple of 8: packed rows end inside a byte, Adam7 passes are uneven
  spec.height = 9;
  spec.bit_depth = bit_depth;
  spec.color = color;
  spec.interlaced = interlaced;
  const int channels = png_channels(color);
  for (int i = 0; i < spec.width * spec.height * channels; ++i)
    spec.samples.push_back(static_cast<std::uint16_t>((i * 2654435761u) >> 7) % (1u << bit_depth));
  if (color == palette) {
    for (int entry = 0; entry < (1 << bit_depth); ++entry)
      for (int c = 0; c < 3; ++c)
        spec.palette.push_back(static_cast<std::uint8_t>(entry * 41 + c * 90));
  }
  return spec;
}

std::string name(const char* color, int bit_depth, bool interlaced, const char* extra = "") {
  return std::string("valid_") + color + "_" + std::to_string(bit_depth) + "bit" +
         (interlaced ? "_interlaced" : "") + extra + ".png";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: make_png_seeds FOLDER\n";
    return 2;
  }
  const std::string folder = argv[1];
  const auto write = [&](const std::string& file, const std::string& bytes) {
    std::ofstream(folder + "/" + file, std::ios::binary) << bytes;
  };
  for (const bool interlaced : {false, true}) {
    for (const int depth : {1, 2, 4, 8, 16})
      write(name("grey", depth, interlaced), encode_test_png(image(depth, grey, interlaced)));
    for (const int depth : {8, 16}) {
      write(name("grey_alpha", depth, interlaced),
            encode_test_png(image(depth, grey_alpha, interlaced)));
      write(name("rgb", depth, interlaced), encode_test_png(image(depth, rgb, interlaced)));
      write(name("rgba", depth, interlaced), encode_test_png(image(depth, rgba, interlaced)));
    }
    for (const int depth : {1, 2, 4, 8}) {
      PngSpec spec = image(depth, palette, interlaced);
      write(name("palette", depth, interlaced), encode_test_png(spec));
      spec.transparency = std::string("\x00\x80", 2);
      write(name("palette", depth, interlaced, "_trns"), encode_test_png(spec));
    }
  }
  PngSpec keyed = image(16, grey, false);
  keyed.transparency = std::string("\x12\x34", 2);
  write("valid_grey_16bit_trns_key.png", encode_test_png(keyed));
  PngSpec rgb_keyed = image(8, rgb, false);
  rgb_keyed.transparency = std::string("\0\x10\0\x20\0\x30", 6);
  write("valid_rgb_8bit_trns_key.png", encode_test_png(rgb_keyed));

  wobble::RgbaImage written;
  written.width = 24;
  written.height = 10;
  for (int i = 0; i < written.width * written.height * 4; ++i)
    written.pixels.push_back(static_cast<unsigned char>(i * 13 ^ i / 96));
  write("valid_written_by_wobble.png", wobble::encode_png(written));

  const std::string good = encode_test_png(image(8, rgba, false));
  write("broken_truncated_in_header.png", good.substr(0, 20));
  write("broken_truncated_in_pixels.png", good.substr(0, good.size() / 2));
  std::string crc = good;
  crc[good.size() / 2] ^= 0x10;
  write("broken_crc.png", crc);
  std::string adler = good;
  adler[good.size() - 17] ^= 0x01;
  write("broken_zlib_checksum.png", adler);
  write("broken_signature.png", "GIF89a" + good.substr(6));
  write("broken_too_large.png", png_header(16384, 16384) + good.substr(33));
  PngSpec no_palette = image(4, palette, false);
  no_palette.palette.clear();
  write("broken_palette_missing.png", encode_test_png(no_palette));
  return 0;
}

#ifndef WOBBLE_TESTS_IO_PNG_BYTES_H
#define WOBBLE_TESTS_IO_PNG_BYTES_H

#include <cstdint>
#include <string>
#include <vector>

namespace wobble::testing {

// PNG files of every kind the format allows, written by the tests' own small encoder (stored
// deflate blocks, no compression), so that the decoder is tried on bit depths, colour types,
// palettes, tRNS and interlacing that Wobble itself never writes.

// The CRC-32 of PNG chunks (and zlib's Adler-32 is in png_bytes.cpp's encoder).
std::uint32_t png_crc32(const std::string& bytes);

// A zlib stream of `data` in stored (uncompressed) deflate blocks.
std::string zlib_stored(const std::string& data);

// One chunk: length, type, data and its CRC.
std::string png_chunk(const std::string& type, const std::string& data);

// The signature and a valid IHDR chunk of an 8-bit RGBA image of the given size, and nothing
// else: all that a header check reads.
std::string png_header(std::uint32_t width, std::uint32_t height);

// Colour types, as the PNG specification numbers them.
enum PngColor : int { grey = 0, rgb = 2, palette = 3, grey_alpha = 4, rgba = 6 };

struct PngSpec {
  int width = 1;
  int height = 1;
  int bit_depth = 8;  // 1, 2, 4, 8 or 16, as the colour type allows
  int color = rgba;
  bool interlaced = false;  // Adam7
  // width × height × channels samples, rows from the top, each below 2^bit_depth (palette:
  // an index).
  std::vector<std::uint16_t> samples;
  std::vector<std::uint8_t> palette;  // palette: 3 bytes an entry
  std::string transparency;           // the tRNS chunk's data, or "" for none
};

// The whole file.
std::string encode_test_png(const PngSpec& spec);

// Channels per pixel of a colour type.
int png_channels(int color);

}  // namespace wobble::testing

#endif

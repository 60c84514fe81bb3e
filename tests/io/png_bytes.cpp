#include "png_bytes.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace wobble::testing {

namespace {

void put32(std::string& bytes, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8)
    bytes.push_back(static_cast<char>((value >> shift) & 0xff));
}

}  // namespace

// Header, blocks of at most 65,535 bytes, Adler-32.
std::string zlib_stored(const std::string& data) {
  std::string out("\x78\x01", 2);
  std::size_t at = 0;
  do {
    const std::size_t length = std::min<std::size_t>(65535, data.size() - at);
    const bool last = at + length == data.size();
    out.push_back(last ? 1 : 0);
    out.push_back(static_cast<char>(length & 0xff));
    out.push_back(static_cast<char>(length >> 8));
    out.push_back(static_cast<char>(~length & 0xff));
    out.push_back(static_cast<char>((~length >> 8) & 0xff));
    out.append(data, at, length);
    at += length;
  } while (at < data.size());
  std::uint32_t a = 1, b = 0;
  for (const char c : data) {
    a = (a + static_cast<unsigned char>(c)) % 65521;
    b = (b + a) % 65521;
  }
  put32(out, (b << 16) | a);
  return out;
}

namespace {

// The rows of the sub-image of pixels (x0 + i dx, y0 + j dy), each a filter byte (0, none) and
// the samples packed most significant bit first (16-bit: big-endian).
void append_rows(const PngSpec& spec, int x0, int y0, int dx, int dy, std::string& out) {
  const int channels = png_channels(spec.color);
  for (int y = y0; y < spec.height; y += dy) {
    if (x0 >= spec.width) return;  // an empty pass has no rows at all
    out.push_back(0);
    int bits = 0, accumulated = 0;
    for (int x = x0; x < spec.width; x += dx) {
      for (int c = 0; c < channels; ++c) {
        const std::uint16_t sample = spec.samples[(y * spec.width + x) * channels + c];
        if (spec.bit_depth == 16) {
          out.push_back(static_cast<char>(sample >> 8));
          out.push_back(static_cast<char>(sample & 0xff));
          continue;
        }
        accumulated = (accumulated << spec.bit_depth) | sample;
        bits += spec.bit_depth;
        if (bits == 8) {
          out.push_back(static_cast<char>(accumulated));
          bits = accumulated = 0;
        }
      }
    }
    if (bits > 0) out.push_back(static_cast<char>(accumulated << (8 - bits)));
  }
}

}  // namespace

std::uint32_t png_crc32(const std::string& bytes) {
  std::uint32_t crc = 0xffffffffu;
  for (const char c : bytes) {
    crc ^= static_cast<unsigned char>(c);
    for (int bit = 0; bit < 8; ++bit)
      crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xffffffffu;
}

std::string png_chunk(const std::string& type, const std::string& data) {
  std::string chunk;
  put32(chunk, static_cast<std::uint32_t>(data.size()));
  chunk += type + data;
  put32(chunk, png_crc32(type + data));
  return chunk;
}

int png_channels(int color) {
  switch (color) {
    case grey:
    case palette:
      return 1;
    case grey_alpha:
      return 2;
    case rgb:
      return 3;
    default:
      return 4;
  }
}

std::string png_header(std::uint32_t width, std::uint32_t height) {
  std::string ihdr;
  put32(ihdr, width);
  put32(ihdr, height);
  ihdr += std::string("\x08\x06\x00\x00\x00", 5);  // 8-bit RGBA, no interlace
  return std::string("\x89PNG\r\n\x1a\n", 8) + png_chunk("IHDR", ihdr);
}

std::string encode_test_png(const PngSpec& spec) {
  if (spec.samples.size() !=
      static_cast<std::size_t>(spec.width) * spec.height * png_channels(spec.color)) {
    throw std::invalid_argument("encode_test_png: the sample count does not match the size");
  }
  std::string ihdr;
  put32(ihdr, static_cast<std::uint32_t>(spec.width));
  put32(ihdr, static_cast<std::uint32_t>(spec.height));
  ihdr.push_back(static_cast<char>(spec.bit_depth));
  ihdr.push_back(static_cast<char>(spec.color));
  ihdr += std::string("\0\0", 2);
  ihdr.push_back(spec.interlaced ? 1 : 0);

  std::string raw;
  if (spec.interlaced) {
    // Adam7: the start and step of each of the seven passes, in x and in y.
    constexpr std::array<std::array<int, 4>, 7> passes{{{0, 0, 8, 8},
                                                        {4, 0, 8, 8},
                                                        {0, 4, 4, 8},
                                                        {2, 0, 4, 4},
                                                        {0, 2, 2, 4},
                                                        {1, 0, 2, 2},
                                                        {0, 1, 1, 2}}};
    for (const auto& pass : passes)
      append_rows(spec, pass[0], pass[1], pass[2], pass[3], raw);
  } else {
    append_rows(spec, 0, 0, 1, 1, raw);
  }

  std::string file = std::string("\x89PNG\r\n\x1a\n", 8) + png_chunk("IHDR", ihdr);
  if (!spec.palette.empty()) {
    file += png_chunk("PLTE", std::string(spec.palette.begin(), spec.palette.end()));
  }
  if (!spec.transparency.empty()) file += png_chunk("tRNS", spec.transparency);
  file += png_chunk("IDAT", zlib_stored(raw));
  file += png_chunk("IEND", "");
  return file;
}

}  // namespace wobble::testing

#ifndef WOBBLE_TESTS_IO_PNG_HEADER_H
#define WOBBLE_TESTS_IO_PNG_HEADER_H

#include <string>

namespace wobble::testing {

// The signature and header chunk of a PNG of the given size (8-bit RGBA), which is all a header
// check reads; the CRC is left 0, which stb_image does not check.
inline std::string png_header(unsigned width, unsigned height) {
  std::string bytes = "\x89PNG\r\n\x1a\n";
  const auto put32 = [&bytes](unsigned value) {
    for (int shift = 24; shift >= 0; shift -= 8)
      bytes.push_back(static_cast<char>((value >> shift) & 0xff));
  };
  put32(13);
  bytes += "IHDR";
  put32(width);
  put32(height);
  bytes += std::string("\x08\x06\x00\x00\x00", 5);  // 8-bit RGBA, no interlace
  put32(0);
  return bytes;
}

}  // namespace wobble::testing

#endif

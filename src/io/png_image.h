#ifndef WOBBLE_IO_PNG_IMAGE_H
#define WOBBLE_IO_PNG_IMAGE_H

#include <string>
#include <vector>

namespace wobble {

// An 8-bit RGBA image, rows from the top, 4 bytes per pixel.
struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> pixels;  // width × height × 4

  const unsigned char* pixel(int x, int y) const { return pixels.data() + 4 * (y * width + x); }
};

// Encode as PNG (stb_image_write). The same image always gives the same bytes.
std::string encode_png(const RgbaImage& image);

// Write a PNG atomically (temporary file, then rename): an interrupted run never leaves a half
// image. Throws OutputError when the file cannot be written.
void write_png(const std::string& path, const RgbaImage& image);

// Read a PNG (or any image stb_image reads) as RGBA. Throws InputError naming the file and why
// it could not be read.
RgbaImage read_png(const std::string& path);

}  // namespace wobble

#endif

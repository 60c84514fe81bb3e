#include "png_image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <stdexcept>

#include "io/atomic_file.h"
#include "sim/input_error.h"

namespace wobble {

namespace {

void append_bytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), size);
}

}  // namespace

std::string encode_png(const RgbaImage& image) {
  if (image.width < 1 || image.height < 1 ||
      image.pixels.size() != 4 * static_cast<std::size_t>(image.width) * image.height) {
    throw std::invalid_argument("encode_png: the pixel count does not match the size");
  }
  std::string bytes;
  if (stbi_write_png_to_func(append_bytes, &bytes, image.width, image.height, 4,
                             image.pixels.data(), 4 * image.width) == 0) {
    throw OutputError("could not encode a " + std::to_string(image.width) + "x" +
                      std::to_string(image.height) + " PNG");
  }
  return bytes;
}

void write_png(const std::string& path, const RgbaImage& image) {
  write_file_atomically(path, encode_png(image));
}

RgbaImage read_png(const std::string& path) {
  int width = 0, height = 0, channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &width, &height, &channels, 4);
  if (data == nullptr) {
    throw InputError(path + ": not a readable image (" + stbi_failure_reason() + ")");
  }
  RgbaImage image;
  image.width = width;
  image.height = height;
  image.pixels.assign(data, data + 4 * static_cast<std::size_t>(width) * height);
  stbi_image_free(data);
  return image;
}

}  // namespace wobble

#include "png_image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <stdexcept>

#include "io/atomic_file.h"
#include "io/input_file.h"
#include "io/input_file_limits.h"
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

namespace {

// stb_image reads through these from an InputFile, so the file is opened with its checks and
// read once.
int read_callback(void* user, char* data, int size) {
  return static_cast<int>(
      static_cast<InputFile*>(user)->read(data, static_cast<std::size_t>(size)));
}
void skip_callback(void* user, int bytes) {
  static_cast<InputFile*>(user)->skip(bytes);
}
int end_callback(void* user) {
  return static_cast<InputFile*>(user)->at_end() ? 1 : 0;
}
constexpr stbi_io_callbacks file_callbacks{read_callback, skip_callback, end_callback};

// Why an image of this header cannot be read with `max_side`, or "".
std::string size_problem(int width, int height, int max_side) {
  if (width <= max_side && height <= max_side) return "";
  return "is " + std::to_string(width) + "x" + std::to_string(height) +
         " pixels, above Wobble's limit of " + std::to_string(max_side) + " pixels a side";
}

}  // namespace

RgbaImage read_png(const std::string& path, int max_side) {
  InputFile file(path, png_file);
  int width = 0, height = 0, channels = 0;
  if (stbi_info_from_callbacks(&file_callbacks, &file, &width, &height, &channels) == 0) {
    throw InputError(path + ": not a readable image (" + stbi_failure_reason() + ")");
  }
  const std::string problem = size_problem(width, height, max_side);
  if (!problem.empty()) throw InputError(path + ": " + problem);
  file.rewind();
  unsigned char* data =
      stbi_load_from_callbacks(&file_callbacks, &file, &width, &height, &channels, 4);
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

std::string texture_problem(const std::string& path) {
  try {
    InputFile file(path, png_file);
    int width = 0, height = 0, channels = 0;
    if (stbi_info_from_callbacks(&file_callbacks, &file, &width, &height, &channels) == 0) {
      return std::string("is not a readable image (") + stbi_failure_reason() + "), expected " +
             png_file.what;
    }
    return size_problem(width, height, max_texture_side);
  } catch (const InputError& error) {
    // InputFile's message starts with the path, which the caller gives its own way.
    const std::string message = error.what();
    return message.compare(0, path.size() + 2, path + ": ") == 0 ? message.substr(path.size() + 2)
                                                                 : message;
  }
}

}  // namespace wobble

#include "png_image.h"

#include <spng.h>

#include <memory>
#include <stdexcept>

#include "io/atomic_file.h"
#include "io/input_file.h"
#include "io/input_file_limits.h"
#include "sim/input_error.h"

namespace wobble {

namespace {

struct ContextDeleter {
  void operator()(spng_ctx* context) const { spng_ctx_free(context); }
};
using Context = std::unique_ptr<spng_ctx, ContextDeleter>;

Context new_context(int flags) {
  Context context(spng_ctx_new(flags));
  if (!context) throw std::bad_alloc();
  return context;
}

// Ancillary chunks (text, colour profiles) are never used; these bound what a hostile file can
// make libspng hold of them: no single chunk above 1 MiB, 4 MiB in all, at most 256 chunks.
constexpr std::size_t max_chunk_bytes = 1 << 20;
constexpr std::size_t max_chunk_cache_bytes = 4 << 20;
constexpr int max_chunk_count = 256;

// libspng reads through this from an InputFile, so the file is opened with its checks and read
// once: it asks for exactly `length` bytes, and a short read is the end of the file.
int read_from_file(spng_ctx*, void* user, void* destination, std::size_t length) {
  auto& file = *static_cast<InputFile*>(user);
  auto* bytes = static_cast<char*>(destination);
  std::size_t got = 0;
  try {
    while (got < length) {
      const std::size_t read = file.read(bytes + got, length - got);
      if (read == 0) return SPNG_IO_EOF;
      got += read;
    }
  } catch (const InputError&) {
    return SPNG_IO_ERROR;  // a read error or a file that grew past its limit
  }
  return 0;
}

// A decoder reading `file`, with the limits above. The CRC of every chunk read and the zlib
// checksum are checked (libspng's defaults). The image size is checked by the caller from the
// header, which names it in the message (libspng's own limit only says "exceeded").
Context new_decoder(InputFile& file) {
  Context context = new_context(0);
  spng_set_png_stream(context.get(), read_from_file, &file);
  spng_set_chunk_limits(context.get(), max_chunk_bytes, max_chunk_cache_bytes);
  spng_set_option(context.get(), SPNG_CHUNK_COUNT_LIMIT, max_chunk_count);
  return context;
}

// Why an image of this header cannot be read with `max_side`, or "".
std::string size_problem(std::uint32_t width, std::uint32_t height, int max_side) {
  const auto side = static_cast<std::uint32_t>(max_side);
  if (width <= side && height <= side) return "";
  return "is " + std::to_string(width) + "x" + std::to_string(height) +
         " pixels, above Wobble's limit of " + std::to_string(max_side) + " pixels a side";
}

std::string not_readable(int error) {
  return std::string("is not a readable image (") + spng_strerror(error) + "), expected " +
         png_file.what;
}

// Reads the signature and the IHDR chunk only, into `header`. Returns "" or why the image
// cannot be read with `max_side`.
std::string read_header(spng_ctx* context, spng_ihdr& header, int max_side) {
  const int error = spng_get_ihdr(context, &header);
  if (error != 0) return not_readable(error);
  return size_problem(header.width, header.height, max_side);
}

int write_to_string(spng_ctx*, void* user, void* source, std::size_t length) {
  static_cast<std::string*>(user)->append(static_cast<const char*>(source), length);
  return 0;
}

}  // namespace

std::string encode_png(const RgbaImage& image) {
  if (image.width < 1 || image.height < 1 ||
      image.pixels.size() != 4 * static_cast<std::size_t>(image.width) * image.height) {
    throw std::invalid_argument("encode_png: the pixel count does not match the size");
  }
  Context context = new_context(SPNG_CTX_ENCODER);
  std::string bytes;
  spng_set_png_stream(context.get(), write_to_string, &bytes);
  spng_ihdr header{};
  header.width = static_cast<std::uint32_t>(image.width);
  header.height = static_cast<std::uint32_t>(image.height);
  header.bit_depth = 8;
  header.color_type = SPNG_COLOR_TYPE_TRUECOLOR_ALPHA;
  int error = spng_set_ihdr(context.get(), &header);
  if (error == 0) {
    error = spng_encode_image(context.get(), image.pixels.data(), image.pixels.size(), SPNG_FMT_PNG,
                              SPNG_ENCODE_FINALIZE);
  }
  if (error != 0) {
    throw OutputError("could not encode a " + std::to_string(image.width) + "x" +
                      std::to_string(image.height) + " PNG: " + spng_strerror(error));
  }
  return bytes;
}

void write_png(const std::string& path, const RgbaImage& image) {
  write_output_file(path, encode_png(image));
}

RgbaImage read_png(const std::string& path, int max_side) {
  InputFile file(path, png_file);
  Context context = new_decoder(file);
  spng_ihdr header{};
  const std::string problem = read_header(context.get(), header, max_side);
  if (!problem.empty()) throw InputError(path + ": " + problem);
  RgbaImage image;
  image.width = static_cast<int>(header.width);
  image.height = static_cast<int>(header.height);
  // Any bit depth (1 to 16), grey, palette or colour, with or without alpha or a tRNS colour,
  // interlaced or not, comes out as 8-bit RGBA; no gamma is applied (the pixels are used as
  // stored, like the PNGs Wobble writes).
  image.pixels.resize(4 * static_cast<std::size_t>(image.width) * image.height);
  const int error = spng_decode_image(context.get(), image.pixels.data(), image.pixels.size(),
                                      SPNG_FMT_RGBA8, SPNG_DECODE_TRNS);
  if (error != 0) {
    throw InputError(path + ": " + not_readable(error));
  }
  return image;
}

std::string texture_problem(const std::string& path) {
  try {
    InputFile file(path, png_file);
    Context context = new_decoder(file);
    spng_ihdr header{};
    return read_header(context.get(), header, max_texture_side);
  } catch (const InputError& error) {
    // InputFile's message starts with the path, which the caller gives its own way.
    const std::string message = error.what();
    return message.compare(0, path.size() + 2, path + ": ") == 0 ? message.substr(path.size() + 2)
                                                                 : message;
  }
}

}  // namespace wobble

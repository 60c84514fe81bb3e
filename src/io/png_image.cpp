#include "png_image.h"

#include <spng.h>

#include <memory>
#include <stdexcept>
#include <vector>

#include "io/atomic_file.h"
#include "io/input_file.h"
#include "io/input_file_limits.h"
#include "io/png_chunks.h"
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

// What libspng reads: the file, opened with InputFile's checks and read once, and the chunks
// followed as their bytes go by, so that damage is named by its chunk.
struct PngSource {
  InputFile& file;
  PngChunks chunks;
};

// libspng reads through this: it asks for exactly `length` bytes, and a short read is the end
// of the file.
int read_from_file(spng_ctx*, void* user, void* destination, std::size_t length) {
  auto& source = *static_cast<PngSource*>(user);
  auto* bytes = static_cast<char*>(destination);
  std::size_t got = 0;
  try {
    while (got < length) {
      const std::size_t read = source.file.read(bytes + got, length - got);
      if (read == 0) break;
      got += read;
    }
  } catch (const InputError&) {
    return SPNG_IO_ERROR;  // a read error or a file that grew past its limit
  }
  source.chunks.feed(reinterpret_cast<const unsigned char*>(bytes), got);
  if (got < length) {
    source.chunks.end_of_file();
    return SPNG_IO_EOF;
  }
  return 0;
}

// A decoder reading `source`, with the limits above. The CRC of every chunk, critical or
// ancillary, is checked (libspng's default discards an ancillary chunk whose CRC is wrong and
// goes on), as is the zlib checksum of the pixels. The image size is checked by the caller from
// the header, which names it in the message (libspng's own limit only says "exceeded").
Context new_decoder(PngSource& source) {
  Context context = new_context(0);
  spng_set_png_stream(context.get(), read_from_file, &source);
  spng_set_crc_action(context.get(), SPNG_CRC_ERROR, SPNG_CRC_ERROR);
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

// Why libspng stopped with `error`: damage the chunks show, named by its chunk, or else
// libspng's own words. libspng stops at the first thing wrong, often before the CRC of the chunk
// it was in (a flipped bit in IDAT breaks the zlib stream first), so the rest of the file is
// followed too.
std::string decode_problem(PngSource& source, int error) {
  if (source.chunks.damage().empty() && !source.chunks.complete()) {
    try {
      std::vector<char> block(64 * 1024);
      while (const std::size_t got = source.file.read(block.data(), block.size())) {
        source.chunks.feed(reinterpret_cast<const unsigned char*>(block.data()), got);
      }
      source.chunks.end_of_file();
    } catch (const InputError&) {
      // A read error: libspng's words below.
    }
  }
  if (!source.chunks.damage().empty()) return "the PNG is damaged: " + source.chunks.damage();
  return std::string("is not a readable image (") + spng_strerror(error) + "), expected " +
         png_file.what;
}

// Decodes the whole PNG at `path`, up to and including its IEND chunk: into `image` when one is
// given, else row by row into one row's buffer, only to check it. Returns "" or why it cannot
// be read (after the path, for a message).
std::string decode_png(const std::string& path, int max_side, RgbaImage* image) {
  InputFile file(path, png_file);
  PngSource source{file, {}};
  Context context = new_decoder(source);
  spng_ihdr header{};
  int error = spng_get_ihdr(context.get(), &header);
  if (error != 0) return decode_problem(source, error);
  const std::string too_large = size_problem(header.width, header.height, max_side);
  if (!too_large.empty()) return too_large;
  // Any bit depth (1 to 16), grey, palette or colour, with or without alpha or a tRNS colour,
  // interlaced or not, comes out as 8-bit RGBA; no gamma is applied (the pixels are used as
  // stored, like the PNGs Wobble writes).
  const std::size_t row_bytes = 4 * static_cast<std::size_t>(header.width);
  if (image != nullptr) {
    image->width = static_cast<int>(header.width);
    image->height = static_cast<int>(header.height);
    image->pixels.resize(row_bytes * header.height);
    error = spng_decode_image(context.get(), image->pixels.data(), image->pixels.size(),
                              SPNG_FMT_RGBA8, SPNG_DECODE_TRNS);
  } else {
    std::vector<unsigned char> row(row_bytes);
    error = spng_decode_image(context.get(), nullptr, 0, SPNG_FMT_RGBA8,
                              SPNG_DECODE_TRNS | SPNG_DECODE_PROGRESSIVE);
    while (error == 0)
      error = spng_decode_row(context.get(), row.data(), row.size());
    if (error == SPNG_EOI) error = 0;
  }
  // The chunks after the pixels, to IEND: their CRCs, and that the file is whole.
  if (error == 0) error = spng_decode_chunks(context.get());
  if (error != 0) return decode_problem(source, error);
  if (!source.chunks.complete()) {
    return "the PNG is damaged: " + (source.chunks.damage().empty()
                                         ? std::string("the file ends without the IEND chunk")
                                         : source.chunks.damage());
  }
  return "";
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
  RgbaImage image;
  const std::string problem = decode_png(path, max_side, &image);
  if (!problem.empty()) throw InputError(path + ": " + problem);
  return image;
}

std::string texture_problem(const std::string& path) {
  try {
    return decode_png(path, max_texture_side, nullptr);
  } catch (const InputError& error) {
    // InputFile's message starts with the path, which the caller gives its own way.
    const std::string message = error.what();
    return message.compare(0, path.size() + 2, path + ": ") == 0 ? message.substr(path.size() + 2)
                                                                 : message;
  }
}

}  // namespace wobble

#ifndef WOBBLE_IO_PNG_IMAGE_H
#define WOBBLE_IO_PNG_IMAGE_H

#include <string>
#include <vector>

#include "io/input_file_limits.h"

namespace wobble {

// An 8-bit RGBA image, rows from the top, 4 bytes per pixel.
struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> pixels;  // width × height × 4

  const unsigned char* pixel(int x, int y) const { return pixels.data() + 4 * (y * width + x); }
};

// Encode as an 8-bit RGBA PNG (libspng, zlib's default compression). The same image always gives
// the same bytes.
std::string encode_png(const RgbaImage& image);

// Write a PNG atomically (temporary file, then rename): an interrupted run never leaves a half
// image. Throws OutputError when the file cannot be written.
void write_png(const std::string& path, const RgbaImage& image);

// Read a PNG as 8-bit RGBA with libspng, reading the file once: any bit depth (1, 2, 4, 8, 16;
// 16-bit samples keep their high byte), grey, palette or colour, with alpha or a tRNS colour,
// interlaced or not. No gamma or colour profile is applied. The header is read first, and an
// image wider or taller than `max_side` pixels is refused before any pixel is decoded. The
// whole file is read, to its IEND chunk: the CRC of every chunk (critical or ancillary, before
// or after the pixels) and the pixel data's zlib checksum are checked, and a file that ends
// inside a chunk or before IEND is refused, naming the chunk: "PATH: the PNG is damaged: chunk
// IDAT checksum is wrong" (see PngChunks). The ancillary chunks Wobble never uses (text,
// profiles) are held to libspng's chunk limits, set to 1 MiB a chunk and 4 MiB in all, so that
// compressed text is never inflated past them. Throws InputError naming the file and why it
// could not be read: not a regular file, larger than png_file.max_bytes
// (io/input_file_limits.h), not a PNG, damaged or truncated, or too large.
RgbaImage read_png(const std::string& path, int max_side = max_texture_side);

// Why the image at `path` cannot be a texture, or "" when it can: every check of read_png with
// max_texture_side, the whole file decoded row by row into one row's buffer (so it takes little
// memory), so that a scene with a bad or damaged texture is refused when it is loaded, drawn or
// not, and a texture it accepts is one read_png reads. The reason reads after the path ("is a
// folder, expected a PNG texture", "the PNG is damaged: chunk IDAT checksum is wrong").
std::string texture_problem(const std::string& path);

}  // namespace wobble

#endif

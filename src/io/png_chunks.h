#ifndef WOBBLE_IO_PNG_CHUNKS_H
#define WOBBLE_IO_PNG_CHUNKS_H

#include <cstddef>
#include <cstdint>
#include <string>

namespace wobble {

// Follows the chunks of a PNG file as its bytes go by, in order (the bytes a decoder reads,
// handed over as it reads them), and finds the damage a decoder may not name or may not look
// for: a chunk whose CRC-32 does not match its type and data (critical or ancillary, before or
// after the pixels), and a file that ends inside a chunk or before its IEND chunk. A file that
// does not start with the PNG signature is left to the decoder to refuse (damage() stays "").
class PngChunks {
 public:
  // The next `size` bytes of the file.
  void feed(const unsigned char* bytes, std::size_t size);
  // The file has ended (a read found no more bytes).
  void end_of_file();

  // The first damage found, or "": "chunk IDAT checksum is wrong", "the file ends inside
  // chunk IDAT", "the file ends after chunk IDAT, without the IEND chunk".
  const std::string& damage() const { return damage_; }
  // Whether the IEND chunk has been read whole, with a correct CRC.
  bool complete() const { return phase_ == Phase::after_end; }

 private:
  enum class Phase { signature, header, data, crc, after_end, not_png };

  void start_chunk();
  void end_chunk();
  std::string type_name() const;

  Phase phase_ = Phase::signature;
  unsigned char field_[8] = {};  // the signature, a chunk's length and type, or its CRC so far
  std::size_t field_bytes_ = 0;
  std::uint32_t data_left_ = 0;  // bytes of the current chunk's data still to come
  std::uint32_t crc_ = 0;        // running CRC-32 of the current chunk's type and data
  char type_[4] = {};
  std::string last_type_;  // the latest chunk read whole
  std::string damage_;
};

// The CRC-32 (ISO 3309, as PNG and zlib use it) of `size` bytes, continuing from `crc` (0 to
// start).
std::uint32_t crc32_update(std::uint32_t crc, const unsigned char* bytes, std::size_t size);

}  // namespace wobble

#endif

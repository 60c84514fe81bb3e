#include "png_chunks.h"

#include <algorithm>
#include <array>

namespace wobble {

namespace {

constexpr unsigned char png_signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

const std::array<std::uint32_t, 256>& crc_table() {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> entries{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int bit = 0; bit < 8; ++bit)
        c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      entries[n] = c;
    }
    return entries;
  }();
  return table;
}

std::uint32_t big_endian(const unsigned char* bytes) {
  return std::uint32_t(bytes[0]) << 24 | std::uint32_t(bytes[1]) << 16 |
         std::uint32_t(bytes[2]) << 8 | std::uint32_t(bytes[3]);
}

}  // namespace

std::uint32_t crc32_update(std::uint32_t crc, const unsigned char* bytes, std::size_t size) {
  const std::array<std::uint32_t, 256>& table = crc_table();
  crc = ~crc;
  for (std::size_t i = 0; i < size; ++i)
    crc = table[(crc ^ bytes[i]) & 0xFF] ^ (crc >> 8);
  return ~crc;
}

std::string PngChunks::type_name() const {
  // A type is four ASCII letters; anything else is shown as '?', so a message stays readable.
  std::string name;
  for (const char c : type_) {
    const bool letter = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
    name += letter ? c : '?';
  }
  return name;
}

void PngChunks::start_chunk() {
  data_left_ = big_endian(field_);
  for (int i = 0; i < 4; ++i)
    type_[i] = static_cast<char>(field_[4 + i]);
  crc_ = crc32_update(0, field_ + 4, 4);
  // A length above 2^31 - 1 is not PNG; the decoder refuses it in its own words.
  phase_ = data_left_ > 0x7FFFFFFFu ? Phase::not_png : Phase::data;
}

void PngChunks::end_chunk() {
  if (big_endian(field_) != crc_ && damage_.empty()) {
    damage_ = "chunk " + type_name() + " checksum is wrong";
  }
  last_type_ = type_name();
  phase_ = last_type_ == "IEND" && damage_.empty() ? Phase::after_end : Phase::header;
}

void PngChunks::feed(const unsigned char* bytes, std::size_t size) {
  std::size_t at = 0;
  while (at < size && phase_ != Phase::after_end && phase_ != Phase::not_png) {
    if (phase_ == Phase::data) {
      const std::size_t take = std::min<std::size_t>(data_left_, size - at);
      crc_ = crc32_update(crc_, bytes + at, take);
      data_left_ -= static_cast<std::uint32_t>(take);
      at += take;
      if (data_left_ == 0) phase_ = Phase::crc;
      continue;
    }
    // The signature, a chunk's length and type, or its CRC: collected whole first.
    const std::size_t wanted = phase_ == Phase::crc ? 4 : 8;
    field_[field_bytes_++] = bytes[at++];
    if (field_bytes_ < wanted) continue;
    field_bytes_ = 0;
    if (phase_ == Phase::signature) {
      bool same = true;
      for (int i = 0; i < 8; ++i)
        same = same && field_[i] == png_signature[i];
      phase_ = same ? Phase::header : Phase::not_png;
    } else if (phase_ == Phase::header) {
      start_chunk();
      if (phase_ == Phase::data && data_left_ == 0) phase_ = Phase::crc;
    } else {
      end_chunk();
    }
  }
}

void PngChunks::end_of_file() {
  if (!damage_.empty() || phase_ == Phase::after_end || phase_ == Phase::not_png ||
      phase_ == Phase::signature) {
    return;
  }
  if (phase_ == Phase::data || phase_ == Phase::crc) {
    damage_ = "the file ends inside chunk " + type_name();
  } else if (field_bytes_ > 0) {
    damage_ = "the file ends inside a chunk's length and type";
  } else if (last_type_.empty()) {
    damage_ = "the file ends after the PNG signature, without any chunk";
  } else {
    damage_ = "the file ends after chunk " + last_type_ + ", without the IEND chunk";
  }
}

}  // namespace wobble

#include "json_file_text.h"

namespace wobble {

JsonFileText::JsonFileText(InputFile& file, std::size_t max_string_bytes)
    : file_(file), block_(64 * 1024), max_string_bytes_(max_string_bytes) {}

void JsonFileText::rewind() {
  file_.rewind();
  position_ = filled_ = read_ = 0;
  end_ = started_ = read_content_ = false;
  newlines_ = 0;
  in_string_ = escaped_ = string_too_long_ = false;
  string_bytes_ = 0;
}

void JsonFileText::fill() {
  if (position_ < filled_ || end_) return;
  position_ = filled_ = 0;
  // The first block is read until it holds 3 bytes (or the whole file), so that a byte-order
  // mark is seen whole even if the system hands the file over in smaller pieces.
  const std::size_t wanted = started_ ? 1 : 3;
  while (filled_ < wanted) {
    const std::size_t got = file_.read(block_.data() + filled_, block_.size() - filled_);
    if (got == 0) break;
    filled_ += got;
  }
  if (!started_ && filled_ >= 3 && block_[0] == '\xEF' && block_[1] == '\xBB' &&
      block_[2] == '\xBF') {
    position_ = 3;
  }
  started_ = true;
  if (position_ == filled_) end_ = true;
}

bool JsonFileText::at_end() {
  fill();
  return end_ || string_too_long_;
}

const char& JsonFileText::current() {
  fill();
  return block_[position_];
}

void JsonFileText::advance() {
  if (at_end()) return;
  const char c = block_[position_++];
  ++read_;
  if (c == '\n') ++newlines_;
  if (c != ' ' && c != '\t' && c != '\r' && c != '\n') read_content_ = true;
  if (!in_string_) {
    in_string_ = c == '"';
    string_bytes_ = 0;
    return;
  }
  if (escaped_) {
    escaped_ = false;
  } else if (c == '\\') {
    escaped_ = true;
  } else if (c == '"') {
    in_string_ = false;
    return;
  }
  if (++string_bytes_ > max_string_bytes_) string_too_long_ = true;
}

long JsonFileText::line_of(std::size_t offset) {
  rewind();
  while (read_ < offset && !at_end())
    advance();
  return line();
}

}  // namespace wobble

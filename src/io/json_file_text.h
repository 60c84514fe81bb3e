#ifndef WOBBLE_IO_JSON_FILE_TEXT_H
#define WOBBLE_IO_JSON_FILE_TEXT_H

#include <cstddef>
#include <iterator>
#include <vector>

#include "io/input_file.h"

namespace wobble {

// The characters of a JSON file for nlohmann's parser, read from an InputFile in blocks of
// 64 KiB, so that parsing a file never holds its whole text: a leading UTF-8 byte-order mark is
// skipped, and the lines read so far are counted, so that a parser's handler can say on which
// line it is. Pass begin() and end() to nlohmann::json::sax_parse or parse.
//
// A string (between unescaped quotes) longer than `max_string_bytes` ends the text where it
// passes the limit, and string_too_long() says so: nlohmann's lexer keeps two copies of the
// token it reads, so a 16 MiB string would otherwise take 50 MB before any handler saw it.
class JsonFileText {
 public:
  // An input iterator over the characters; all copies move together (nlohmann reads each
  // character once).
  class Iterator {
   public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    Iterator() = default;
    explicit Iterator(JsonFileText* text) : text_(text) {}
    reference operator*() const { return text_->current(); }
    Iterator& operator++() {
      text_->advance();
      return *this;
    }
    // Iterators are equal when both are at the end (the end iterator always is).
    bool operator==(const Iterator& other) const { return done() == other.done(); }
    bool operator!=(const Iterator& other) const { return !(*this == other); }

   private:
    bool done() const { return text_ == nullptr || text_->at_end(); }
    JsonFileText* text_ = nullptr;
  };

  // `file` must outlive this; reading starts at its beginning.
  JsonFileText(InputFile& file, std::size_t max_string_bytes);

  Iterator begin() { return Iterator(this); }
  Iterator end() { return Iterator(); }

  // Back to the first character, with the counts reset, for another pass over the file.
  void rewind();
  bool at_end();
  const char& current();  // only when !at_end()
  void advance();

  // Characters read so far (after any byte-order mark), and the line the next one is on.
  std::size_t characters_read() const { return read_; }
  long line() const { return newlines_ + 1; }
  // Whether anything but JSON whitespace (space, tab, CR, LF) has been read.
  bool read_content() const { return read_content_; }
  // Whether the text was ended inside a string longer than max_string_bytes.
  bool string_too_long() const { return string_too_long_; }
  // The line of the character at `offset` (0-based, after any byte-order mark): found by
  // reading the file again from its start, so only for messages.
  long line_of(std::size_t offset);

 private:
  void fill();

  InputFile& file_;
  std::vector<char> block_;
  std::size_t position_ = 0;  // in block_
  std::size_t filled_ = 0;    // bytes of block_ that hold the file
  bool end_ = false;          // the file has no more bytes
  bool started_ = false;      // the first block (and its byte-order mark) has been read
  std::size_t read_ = 0;
  long newlines_ = 0;
  bool read_content_ = false;
  const std::size_t max_string_bytes_;
  bool in_string_ = false;
  bool escaped_ = false;  // the previous character was a backslash inside a string
  std::size_t string_bytes_ = 0;
  bool string_too_long_ = false;
};

}  // namespace wobble

#endif

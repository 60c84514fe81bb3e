#include "read_json_file.h"

#include <algorithm>

#include "io/input_file_limits.h"
#include "read_text_file.h"
#include "sim/input_error.h"

namespace wobble {

namespace {

// A SAX handler that builds nothing and keeps the first error with where it happened. The DOM
// parser throws parse_error for bad syntax but out_of_range, which has no position, for a
// number too large for a double (1e400); through SAX both come with the parser's position.
class FirstError : public nlohmann::json_sax<nlohmann::json> {
 public:
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t position, const std::string&,
                   const nlohmann::json::exception& error) override {
    found = true;
    byte = position;
    what = error.what();
    return false;
  }

  bool found = false;
  std::size_t byte = 0;  // characters read when the error was found
  std::string what;
};

}  // namespace

nlohmann::json read_json_file(const std::string& path) {
  const std::string text = read_text_file(path, scene_json_file);
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
    throw InputError(path + ": the file is empty, expected a JSON object");
  }
  FirstError error;
  nlohmann::json::sax_parse(text, &error);
  if (!error.found) return nlohmann::json::parse(text);

  // nlohmann counts the characters read, so the offending one is text[byte - 1].
  const std::size_t end = std::min(error.byte == 0 ? 0 : error.byte - 1, text.size());
  const long line = 1 + std::count(text.begin(), text.begin() + end, '\n');
  // Keep what follows "... column C: " (a syntax error) or "[json.exception.ID] " (a number out
  // of range), which says what was expected; the line is given in Wobble's own form.
  const std::string& what = error.what;
  const std::size_t column = what.find("column");
  const std::size_t colon = column == std::string::npos ? column : what.find(": ", column);
  const std::size_t bracket = what.find("] ");
  const std::string detail = colon != std::string::npos     ? what.substr(colon + 2)
                             : bracket != std::string::npos ? what.substr(bracket + 2)
                                                            : what;
  throw InputError(path + ": line " + std::to_string(line) +
                   ": malformed JSON: " + one_line(detail));
}

}  // namespace wobble

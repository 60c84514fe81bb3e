#ifndef WOBBLE_SIM_INPUT_ERROR_H
#define WOBBLE_SIM_INPUT_ERROR_H

#include <cstdio>
#include <stdexcept>
#include <string>

namespace wobble {

// `text` with every control character written out, so that nothing read from a file (a key
// holding a line break, a NUL byte in a coordinate) reaches a terminal raw or cuts a message
// short: \n, \r and \t as themselves, any other byte below 0x20 and DEL as \xHH. Everything
// else, backslashes and UTF-8 included, is kept, so escaping twice changes nothing.
inline std::string escape_control_characters(const std::string& text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (const char c : text) {
    if (c == '\n') {
      escaped += "\\n";
    } else if (c == '\r') {
      escaped += "\\r";
    } else if (c == '\t') {
      escaped += "\\t";
    } else if ((c >= 0 && c < 0x20) || c == 0x7f) {
      char code[5];
      std::snprintf(code, sizeof code, "\\x%02x", static_cast<unsigned char>(c));
      escaped += code;
    } else {
      escaped += c;
    }
  }
  return escaped;
}

// Bad input: a scene, mesh, parameter or option that Wobble refuses. The message names what was
// wrong and what was expected; the command line prints it on one line and exits with code 2.
// The message is escaped here, once for every thrower: what() is a C string, so a NUL byte
// quoted from a file would otherwise end the message before it says what was expected.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message)
      : std::runtime_error(escape_control_characters(message)) {}
};

// `text` from a library (a parser's report, say) on one line: line breaks and tabs become
// spaces, other control characters are escaped as above, and trailing spaces go.
inline std::string one_line(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  }
  while (!text.empty() && text.back() == ' ')
    text.pop_back();
  return escape_control_characters(text);
}

}  // namespace wobble

#endif

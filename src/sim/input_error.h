#ifndef WOBBLE_SIM_INPUT_ERROR_H
#define WOBBLE_SIM_INPUT_ERROR_H

#include <stdexcept>
#include <string>

namespace wobble {

// Bad input: a scene, mesh, parameter or option that Wobble refuses. The message names what was
// wrong and what was expected; the command line prints it on one line and exits with code 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// `text` on one line: line breaks and tabs become spaces, other control characters '?', and
// trailing spaces go, so a message quoting a library (a parser's report, say) or bytes of a
// binary file still fits the one-line rule and cannot upset a terminal.
inline std::string one_line(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r' || c == '\t') {
      c = ' ';
    } else if ((c >= 0 && c < 0x20) || c == 0x7f) {
      c = '?';
    }
  }
  while (!text.empty() && text.back() == ' ')
    text.pop_back();
  return text;
}

}  // namespace wobble

#endif

#ifndef WOBBLE_IO_NUMBER_WORD_H
#define WOBBLE_IO_NUMBER_WORD_H

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

namespace wobble {

// How a word of a mesh file reads as a double (strtod, so correctly rounded).
enum class NumberWord {
  finite,      // a finite number, normal or 0
  malformed,   // not a number, or a number with something after it
  not_finite,  // nan, inf, or too large for a double (1e400)
  underflow,   // nonzero but nearer 0 than the smallest normal double (1e-400, 1e-310)
};

inline NumberWord read_number_word(const std::string& word, double& value) {
  errno = 0;
  char* end = nullptr;
  value = std::strtod(word.c_str(), &end);
  // The whole word: a NUL byte inside it must not end it early.
  if (end == word.c_str() || end != word.c_str() + word.size()) return NumberWord::malformed;
  if (!std::isfinite(value)) return NumberWord::not_finite;
  // strtod reports ERANGE for results that lost precision to underflow (0 or subnormal) and for
  // overflow, which gave ±HUGE_VAL above.
  if (errno == ERANGE) return NumberWord::underflow;
  return NumberWord::finite;
}

// What a message says about a word that underflows.
inline std::string underflow_message(const std::string& word) {
  return "'" + word +
         "' underflows: it is nearer 0 than the smallest double (about 2.2e-308); expected 0 or "
         "a number of magnitude at least 2.2e-308";
}

}  // namespace wobble

#endif

#ifndef WOBBLE_SIM_PARSE_NUMBER_H
#define WOBBLE_SIM_PARSE_NUMBER_H

#include <charconv>
#include <optional>
#include <string>

namespace wobble {

// The whole of `text` as a number of type T, or nothing if any of it is not part of one (so
// "2.5" is no int, "1e400" no double, and "" nothing at all). Locale-independent.
template <typename T>
std::optional<T> parse_number(const std::string& text) {
  T value{};
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end) return std::nullopt;
  return value;
}

}  // namespace wobble

#endif

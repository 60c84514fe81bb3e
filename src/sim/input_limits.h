#ifndef WOBBLE_SIM_INPUT_LIMITS_H
#define WOBBLE_SIM_INPUT_LIMITS_H

#include <string>

namespace wobble {

// The largest meshes Wobble accepts from a file. A count in a file header is checked against
// these before anything is read, so that a few bytes asking for billions of vertices are refused
// at once with the limit in the message. Meshes this large already take seconds per step; the
// scene generators' resolution limits keep their meshes far below.
constexpr long max_input_vertices = 10'000'000;
constexpr long max_input_tetrahedra = 6 * max_input_vertices;  // as many as a grid of 6-tet cells

// `count` with thousands separators, as messages show limits: 10000000 → "10,000,000".
inline std::string with_thousands_separators(long count) {
  std::string digits = std::to_string(count);
  const std::size_t first = digits[0] == '-' ? 1 : 0;
  for (std::size_t at = digits.size(); at > first + 3; at -= 3)
    digits.insert(at - 3, ",");
  return digits;
}

}  // namespace wobble

#endif

#ifndef WOBBLE_IO_TEXT_PIECES_H
#define WOBBLE_IO_TEXT_PIECES_H

#include <string>
#include <vector>

namespace wobble {

// "a, b, c": the words joined by ", " (messages listing keys).
std::string comma_joined(const std::vector<std::string>& words);

// Appends the shortest decimal that reads back (strtod, as the readers read) to the same double.
void append_shortest(std::string& text, double value);

}  // namespace wobble

#endif

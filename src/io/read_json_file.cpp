#include "read_json_file.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "sim/input_error.h"

namespace wobble {

nlohmann::json read_json_file(const std::string& path) {
  std::error_code ignored;
  if (!std::filesystem::is_regular_file(path, ignored)) {
    throw InputError(path + ": no such file, expected a scene (JSON)");
  }
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (!in) throw InputError(path + ": could not read the file");
  const std::string text = buffer.str();
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
    throw InputError(path + ": the file is empty, expected a JSON object");
  }
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& error) {
    // nlohmann counts the characters read, so the offending one is text[byte - 1].
    const std::size_t end = std::min(error.byte == 0 ? 0 : error.byte - 1, text.size());
    const long line = 1 + std::count(text.begin(), text.begin() + end, '\n');
    // Keep what follows "... column C: ", which says what was expected; the line is given in
    // Wobble's own form.
    const std::string what = error.what();
    const std::size_t column = what.find("column");
    const std::size_t colon = column == std::string::npos ? column : what.find(": ", column);
    const std::string detail = colon == std::string::npos ? what : what.substr(colon + 2);
    throw InputError(path + ": line " + std::to_string(line) +
                     ": malformed JSON: " + one_line(detail));
  }
}

}  // namespace wobble

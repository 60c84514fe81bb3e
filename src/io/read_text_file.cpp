#include "read_text_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "sim/input_error.h"

namespace wobble {

std::string read_text_file(const std::string& path, const std::string& what) {
  std::error_code ignored;
  if (!std::filesystem::is_regular_file(path, ignored)) {
    throw InputError(path + ": no such file, expected " + what);
  }
  std::ifstream in(path, std::ios::binary);
  std::stringstream contents;
  contents << in.rdbuf();
  if (!in) throw InputError(path + ": could not read the file");
  return contents.str();
}

}  // namespace wobble

#include "app/viewer/window_saves.h"

#include <cstdio>
#include <filesystem>

namespace wobble {

std::string unused_file_name(const std::string& folder, const std::string& stem,
                             const std::string& extension) {
  for (int number = 1;; ++number) {
    char name[32];
    std::snprintf(name, sizeof(name), "-%04d", number);
    const std::filesystem::path path = std::filesystem::path(folder) / (stem + name + extension);
    std::error_code error;
    if (!std::filesystem::exists(path, error)) return path.string();
  }
}

}  // namespace wobble

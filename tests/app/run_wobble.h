#ifndef WOBBLE_TESTS_APP_RUN_WOBBLE_H
#define WOBBLE_TESTS_APP_RUN_WOBBLE_H

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../io/temporary_folder.h"

namespace wobble::testing {

struct Result {
  int exit_code = -1;
  std::string out, err;
};

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Names of everything in `folder`, sorted.
inline std::vector<std::string> sorted_names(const std::string& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Run the wobble executable (WOBBLE_EXECUTABLE) with `arguments`, already shell-quoted where
// needed, and `environment` assignments (e.g. "DISPLAY= ") in front; capture both streams.
inline Result run_wobble(const std::string& arguments, const std::string& environment = "") {
  TemporaryFolder capture;
  const std::string command = environment + " '" + std::string(WOBBLE_EXECUTABLE) + "' " +
                              arguments + " >'" + capture.file("out") + "' 2>'" +
                              capture.file("err") + "' </dev/null";
  const int status = std::system(command.c_str());
  Result result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_text(capture.file("out"));
  result.err = read_text(capture.file("err"));
  return result;
}

#ifdef WOBBLE_HIDE_LIBRARIES_MODULE
// Environment assignments for run_wobble that play a machine without `libraries` (colon-separated
// file names): app/hide_libraries/ preloaded, so that dlopen of them fails.
inline std::string hiding(const std::string& libraries) {
  return "LD_PRELOAD='" + std::string(WOBBLE_HIDE_LIBRARIES_MODULE) + "' WOBBLE_HIDE_LIBRARIES='" +
         libraries + "'";
}
// What glvnd's libGL is called by: what ImGui's own OpenGL backend opened.
inline const std::string no_libgl = "libGL.so.1:libGL.so";
#endif

// In a forked child whose streams are already set up: becomes the wobble executable
// (WOBBLE_EXECUTABLE) run with `arguments`; exits with 127 if it cannot be started.
[[noreturn]] inline void exec_wobble(const std::vector<std::string>& arguments) {
  std::vector<char*> argv{const_cast<char*>(WOBBLE_EXECUTABLE)};
  for (const std::string& argument : arguments)
    argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  execv(WOBBLE_EXECUTABLE, argv.data());
  _exit(127);
}

}  // namespace wobble::testing

#endif

// The atomic write seen from the system calls, with strace: the image's bytes are synced before
// the rename, and its folder after it, so that the rename survives a power cut.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "run_wobble.h"

namespace {

using wobble::testing::Result;
using wobble::testing::run_wobble;
using wobble::testing::TemporaryFolder;

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

// What a traced call returned: the text after its last " = " ("3", "0", "-1 ENOENT (...)").
std::string result_of(const std::string& line) {
  const std::size_t equals = line.rfind(" = ");
  return equals == std::string::npos ? "" : line.substr(equals + 3);
}

TEST(AtomicWriteTrace, TheFolderIsSyncedAfterTheRename) {
  if (std::system("strace -o /dev/null true >/dev/null 2>&1") != 0) {
    GTEST_SKIP() << "strace cannot trace here (not installed, or ptrace is not allowed)";
  }
  TemporaryFolder folder;
  const std::string image = folder.file("shot.png"), trace = folder.file("trace");
  // LeakSanitizer cannot work under ptrace, so the sanitizer build's traced run leaves the leak
  // checks to the other tests (the later setting wins; other builds ignore the variable).
  const char* sanitizer_options = std::getenv("ASAN_OPTIONS");
  const std::string no_leak_check = "ASAN_OPTIONS='" +
                                    std::string(sanitizer_options ? sanitizer_options : "") +
                                    ":detect_leaks=0' ";
  const Result result =
      run_wobble("cloth --headless --frames 1 --width 64 --height 48 --screenshot '" + image + "'",
                 no_leak_check + "strace -f -o '" + trace +
                     "' -e trace=openat,fsync,rename,renameat,renameat2");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::vector<std::string> lines = lines_of(trace);
  const std::string folder_opened = "openat(AT_FDCWD, \"" + folder.path().string() + "\", ";
  std::size_t renamed = lines.size(), data_synced = lines.size();
  std::string folder_fd;
  bool folder_synced = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    if (line.find("rename") != std::string::npos &&
        line.find(", \"" + image + "\"") != std::string::npos && result_of(line) == "0") {
      renamed = i;
    } else if (renamed == lines.size() && line.find("fsync(") != std::string::npos) {
      data_synced = i;
    }
    if (i > renamed && line.find(folder_opened) != std::string::npos &&
        line.find("O_DIRECTORY") != std::string::npos) {
      folder_fd = result_of(line);
    }
    if (!folder_fd.empty() && line.find("fsync(" + folder_fd + ")") != std::string::npos &&
        result_of(line) == "0") {
      folder_synced = true;
    }
  }
  ASSERT_LT(renamed, lines.size()) << "no rename onto the image in the trace";
  EXPECT_LT(data_synced, renamed) << "the bytes are synced before the rename";
  EXPECT_TRUE(folder_synced) << "the folder is opened and synced after the rename";
}

}  // namespace

// A run ended by SIGTERM or SIGINT (Ctrl+C) in the middle of writing its frames leaves the frames
// already written and no temporary file (FRAME.obj.tmp-XXXXXX) behind.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <string>
#include <vector>

#include "run_wobble.h"

namespace {

using wobble::testing::TemporaryFolder;

// Start wobble with `arguments`, its output thrown away; returns its process id.
pid_t start_wobble(const std::vector<std::string>& arguments) {
  const pid_t pid = fork();
  if (pid == 0) {
    const int null = open("/dev/null", O_RDWR);
    dup2(null, 0);
    dup2(null, 1);
    dup2(null, 2);
    wobble::testing::exec_wobble(arguments);
  }
  return pid;
}

// Frames finished so far (names that end in .obj), and whether a temporary file
// (FRAME.obj.tmp-XXXXXX) is there now.
std::size_t count_frames(const std::string& folder, bool& writing) {
  std::error_code error;
  std::size_t count = 0;
  writing = false;
  for (std::filesystem::directory_iterator entry(folder, error), end; !error && entry != end;
       entry.increment(error)) {
    count += entry->path().extension() == ".obj";
    writing = writing || entry->path().filename().string().find(".tmp-") != std::string::npos;
  }
  return count;
}

TEST(Termination, SignalDuringAnObjSequenceLeavesNoTemporaryFile) {
  for (const int signal_number : {SIGTERM, SIGINT, SIGTERM, SIGINT}) {
    TemporaryFolder folder;
    // A cloth large enough that writing each frame (1.5 MB of OBJ, flushed to disk) is a good
    // part of the frame's time, so the signal often lands inside a write.
    std::ofstream(folder.file("cloth.json"))
        << R"({"mesh": {"generator": "cloth", "resolution": 200}, "pins": "top-edge"})";
    const std::string objs = folder.file("objs");
    const pid_t pid = start_wobble({folder.file("cloth.json"), "--headless", "--frames", "1000000",
                                    "--iterations", "1", "--export-obj-sequence", objs});
    ASSERT_GT(pid, 0);
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    // After two frames, the moment a frame is being written: without the clean-up, the
    // signal would leave its temporary file.
    bool writing = false;
    while ((count_frames(objs, writing) < 2 || !writing) &&
           std::chrono::steady_clock::now() < give_up) {
    }
    kill(pid, signal_number);
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    // The signal ended it, as it would have without the clean-up.
    ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status;
    EXPECT_EQ(WTERMSIG(status), signal_number);
    const std::vector<std::string> names = wobble::testing::sorted_names(objs);
    EXPECT_TRUE(writing) << "the signal never came during a write";
    EXPECT_GE(names.size(), 2u);
    for (const std::string& name : names)
      EXPECT_EQ(name.find(".tmp-"), std::string::npos) << name << " left behind";
  }
}

}  // namespace

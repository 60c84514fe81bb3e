// wobble --student DIR builds the student's step with scripts/check-assignment.sh before any
// window: a file that includes /dev/zero is refused in one line that names the compiler's memory
// limit, and a SIGTERM, SIGINT or SIGHUP to wobble during the build leaves no script, launcher,
// g++ or cc1plus running and no temporary folder behind. The build uses the checker tests'
// object cache (CheckAssignment.SeedPasses fills it), so only the student's file is compiled.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "../io/temporary_folder.h"
#include "run_wobble.h"

namespace {

using Clock = std::chrono::steady_clock;
using wobble::testing::TemporaryFolder;

// A copy of the seed with `first_line` put in front of fast_mass_springs_step_sparse.cpp.
void write_submission(const std::string& folder, const std::string& first_line) {
  std::filesystem::create_directories(folder);
  for (const auto& entry : std::filesystem::directory_iterator(WOBBLE_SEED_DIR))
    std::filesystem::copy_file(entry.path(), folder + "/" + entry.path().filename().string());
  const std::string step = folder + "/fast_mass_springs_step_sparse.cpp";
  const std::string text = wobble::testing::read_text(step);
  std::ofstream(step, std::ios::trunc) << first_line << "\n" << text;
}

// What a started wobble needs around it: its own temporary folder (TMPDIR), the checker tests'
// cache (XDG_CACHE_HOME/wobble-check), a marker in its environment that every process it starts
// inherits, and files for its output.
struct Surroundings {
  TemporaryFolder folder;
  std::string temporary = folder.file("tmp");
  std::string marker = "WOBBLE_STUDENT_BUILD_TEST=" + std::to_string(getpid()) + "-" +
                       std::to_string(Clock::now().time_since_epoch().count());
  Surroundings() {
    std::filesystem::create_directories(temporary);
    std::filesystem::create_directories(folder.file("cache"));
    std::filesystem::create_directory_symlink(WOBBLE_CHECK_CACHE,
                                              folder.file("cache/wobble-check"));
  }

  pid_t start(const std::vector<std::string>& arguments) const {
    const pid_t pid = fork();
    if (pid == 0) {
      setenv("TMPDIR", temporary.c_str(), 1);
      setenv("XDG_CACHE_HOME", folder.file("cache").c_str(), 1);
      putenv(const_cast<char*>(marker.c_str()));
      const int null = open("/dev/null", O_RDONLY);
      const int out = open(folder.file("out").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      const int err = open(folder.file("err").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      dup2(null, 0);
      dup2(out, 1);
      dup2(err, 2);
      wobble::testing::exec_wobble(arguments);
    }
    return pid;
  }

  // The processes (not zombies) wobble started, and their names, e.g. "1234 cc1plus".
  std::vector<std::string> processes() const {
    std::vector<std::string> found;
    for (const auto& process : std::filesystem::directory_iterator("/proc")) {
      const std::string name = process.path().filename().string();
      if (name.find_first_not_of("0123456789") != std::string::npos) continue;
      std::ifstream environ(process.path() / "environ", std::ios::binary);
      for (std::string variable; std::getline(environ, variable, '\0');) {
        if (variable != marker) continue;
        std::string command = wobble::testing::read_text((process.path() / "comm").string());
        if (!command.empty() && command.back() == '\n') command.pop_back();
        found.push_back(name + " " + command);
      }
    }
    return found;
  }

  // processes(), once what is ending has had up to 2 s to end (SIGKILL is not instant).
  std::vector<std::string> processes_left() const {
    const auto until = Clock::now() + std::chrono::seconds(2);
    std::vector<std::string> left = processes();
    while (!left.empty() && Clock::now() < until) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      left = processes();
    }
    return left;
  }

  // Whether a compiler wobble started runs on a file of `submission` (its command line names
  // the folder, which the compilers of Wobble's own files do not).
  bool compiling(const std::string& submission) const {
    for (const std::string& process : processes()) {
      const std::size_t space = process.find(' ');
      if (process.substr(space + 1) != "cc1plus") continue;
      const std::string command_line =
          wobble::testing::read_text("/proc/" + process.substr(0, space) + "/cmdline");
      if (command_line.find(submission) != std::string::npos) return true;
    }
    return false;
  }

  std::vector<std::string> temporary_files() const {
    return wobble::testing::sorted_names(temporary);
  }
};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

TEST(StudentBuild, AFileThatIncludesDevZeroIsRefusedNamingTheMemoryLimit) {
  const Surroundings around;
  const std::string submission = around.folder.file("zero");
  write_submission(submission, "#include \"/dev/zero\"");
  const auto start = Clock::now();
  const pid_t pid = around.start({"cloth", "--headless", "--student", submission, "--screenshot",
                                  around.folder.file("out.png")});
  ASSERT_GT(pid, 0);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  ASSERT_TRUE(WIFEXITED(status)) << "status " << status;
  EXPECT_EQ(WEXITSTATUS(status), 2);
  const std::vector<std::string> err =
      lines_of(wobble::testing::read_text(around.folder.file("err")));
  ASSERT_EQ(err.size(), 1u) << wobble::testing::read_text(around.folder.file("err"));
  EXPECT_EQ(err[0].rfind("wobble: --student " + submission + ": ", 0), 0u) << err[0];
  EXPECT_NE(err[0].find("the compiler passed its memory limit of 2 GiB (does the file include "
                        "something that never ends, such as /dev/zero?)"),
            std::string::npos)
      << err[0];
  // 2 GiB of /dev/zero take the compiler about 1.5 s; without the limit it took 5 GB in 16 s.
  EXPECT_LT(seconds, 60.0);
  EXPECT_EQ(around.temporary_files(), std::vector<std::string>());
  EXPECT_EQ(around.processes_left(), std::vector<std::string>());
}

TEST(StudentBuild, ASignalDuringTheBuildLeavesNothingBehind) {
  for (const int signal_number : {SIGTERM, SIGINT, SIGHUP}) {
    SCOPED_TRACE(strsignal(signal_number));
    const Surroundings around;
    // A build that never ends by itself: the compiler waits for a writer on a named pipe.
    const std::string submission = around.folder.file("pipe");
    write_submission(submission, "#include \"never.h\"");
    ASSERT_EQ(mkfifo((submission + "/never.h").c_str(), 0600), 0);
    const pid_t pid = around.start({"cloth", "--headless", "--student", submission, "--screenshot",
                                    around.folder.file("out.png")});
    ASSERT_GT(pid, 0);
    const auto give_up = Clock::now() + std::chrono::seconds(120);
    bool compiling = false;
    while (!(compiling = around.compiling(submission)) && Clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    kill(pid, signal_number);
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(compiling) << "the student's file never reached the compiler: "
                           << wobble::testing::read_text(around.folder.file("err"));
    // The signal ended wobble, as it would have without the clean-up, and only once every
    // process it started had ended and the script had removed its temporary folder.
    ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status;
    EXPECT_EQ(WTERMSIG(status), signal_number);
    EXPECT_EQ(around.processes_left(), std::vector<std::string>());
    EXPECT_EQ(around.temporary_files(), std::vector<std::string>());
  }
}

}  // namespace

// Names that reach the messages are kept on one line, and a cache folder that cannot be made
// says which variable named it and what is in the way.
TEST(StudentBuild, RefusalsStayOnOneLineAndNameWhereTheCacheCameFrom) {
  TemporaryFolder folder;
  const std::string odd = folder.file("my\nsolution");
  std::filesystem::create_directories(odd);
  wobble::testing::Result result =
      wobble::testing::run_wobble("cloth --headless --frames 1 --screenshot '" +
                                  folder.file("s.png") + "' --student '" + odd + "'");
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  EXPECT_NE(result.err.find("my\\nsolution: missing fast_mass_springs_step_sparse.cpp"),
            std::string::npos)
      << result.err;

  std::ofstream(folder.file("not-a-folder")) << "x";
  write_submission(folder.file("seed"), "");
  result = wobble::testing::run_wobble("cloth --headless --frames 1 --screenshot '" +
                                           folder.file("s.png") + "' --student '" +
                                           folder.file("seed") + "'",
                                       "XDG_CACHE_HOME='" + folder.file("not-a-folder") + "'");
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  EXPECT_NE(result.err.find("cannot create the cache folder: " + folder.file("not-a-folder") +
                            " is a file, not a folder (from XDG_CACHE_HOME)"),
            std::string::npos)
      << result.err;
  EXPECT_FALSE(std::filesystem::exists(folder.file("s.png")));
}

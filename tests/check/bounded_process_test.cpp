// The one way a student's code is compiled and run (src/check/sandbox/bounded_process.h), the
// launcher's loop (bounded_run.h) and each check's child (child_process.h): every limit ends
// the program and is named, and nothing it started outlives it: not what stayed in its process
// group, not what left the group (setsid), not when the caller is stopped by a signal. The
// programs are small shell commands; what they leave behind is found by a variable in their
// environment that only this test sets.
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "../io/temporary_folder.h"
#include "check/sandbox/bounded_process.h"
#include "check/sandbox/bounded_run.h"
#include "check/sandbox/child_process.h"

namespace {

using Clock = std::chrono::steady_clock;

// WOBBLE_BOUNDED_TEST=<unique> in this process's environment while it lives, so that every
// program started meanwhile carries it.
class Marker {
 public:
  Marker() {
    static std::atomic<int> count{0};
    value_ = std::to_string(getpid()) + "-" + std::to_string(++count);
    setenv("WOBBLE_BOUNDED_TEST", value_.c_str(), 1);
  }
  ~Marker() { unsetenv("WOBBLE_BOUNDED_TEST"); }
  Marker(const Marker&) = delete;
  Marker& operator=(const Marker&) = delete;

  // The processes (not zombies) whose environment holds it.
  std::vector<pid_t> processes() const {
    const std::string entry = "WOBBLE_BOUNDED_TEST=" + value_;
    std::vector<pid_t> found;
    for (const auto& process : std::filesystem::directory_iterator("/proc")) {
      const std::string name = process.path().filename().string();
      if (name.find_first_not_of("0123456789") != std::string::npos) continue;
      std::ifstream environ(process.path() / "environ", std::ios::binary);
      for (std::string variable; std::getline(environ, variable, '\0');) {
        if (variable == entry) found.push_back(std::atoi(name.c_str()));
      }
    }
    return found;
  }

  // Waits up to `seconds` for every marked process to be gone; true when they are.
  bool all_gone(double seconds = 3.0) const {
    const auto until = Clock::now() + std::chrono::duration<double>(seconds);
    while (!processes().empty()) {
      if (Clock::now() > until) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return true;
  }

 private:
  std::string value_;
};

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

BoundedRun run_shell(const std::string& script, const ProcessLimits& limits,
                     std::size_t messages_limit = 64 << 10) {
  return run_bounded({"sh", "-c", script}, limits, messages_limit, -1, nullptr);
}

TEST(BoundedRun, TheWallClockEndsTheWholeGroup) {
  const Marker marker;
  ProcessLimits limits;
  limits.wall_seconds = 0.5;
  const auto start = Clock::now();
  const BoundedRun run = run_shell("sleep 30 & sleep 31 & wait", limits);
  EXPECT_EQ(run.ending, BoundedRun::kWallClock);
  EXPECT_LT(seconds_since(start), 3.0);  // 0.5 s and the kill, with room for a busy machine
  EXPECT_EQ(limit_words(run, limits, "the compiler"),
            "the compiler took longer than its 0.5 s limit");
  EXPECT_TRUE(marker.all_gone()) << "a sleep of the group outlived it";
}

TEST(BoundedRun, WhatStaysInTheGroupEndsWhenTheProgramEnds) {
  const Marker marker;
  const BoundedRun run = run_shell("sleep 30 & exit 3", ProcessLimits{});
  EXPECT_EQ(run.ending, BoundedRun::kExited);
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(marker.all_gone());
}

TEST(BoundedRun, OrphansThatLeftTheGroupAreEndedByTheSubreaper) {
  ASSERT_TRUE(adopt_orphans());
  const Marker marker;
  // A double fork that leaves the group: setsid puts the sleep in a session of its own.
  const BoundedRun run = run_shell("setsid sleep 30 & exit 0", ProcessLimits{});
  EXPECT_EQ(run.ending, BoundedRun::kExited);
  // The group's kill cannot reach it: it is still there, this process's child now.
  EXPECT_FALSE(marker.all_gone(0.2)) << "expected the setsid sleep to survive the group's kill";
  EXPECT_GE(end_every_child(), 1);
  EXPECT_TRUE(marker.all_gone());
}

TEST(BoundedRun, TheCpuLimitIsNamed) {
  ProcessLimits limits;
  limits.wall_seconds = 30;
  limits.cpu_seconds = 1;
  const auto start = Clock::now();
  const BoundedRun run = run_shell("while :; do :; done", limits);
  EXPECT_EQ(run.ending, BoundedRun::kCpuTime);
  EXPECT_LT(seconds_since(start), 10.0);
  EXPECT_EQ(limit_words(run, limits, "the compiler"),
            "the compiler passed its CPU time limit of 1 s");
}

TEST(BoundedRun, TheFileSizeLimitHoldsAndIsNamed) {
  wobble::testing::TemporaryFolder folder;
  ProcessLimits limits;
  limits.file_bytes = 1 << 20;
  const BoundedRun run =
      run_shell("head -c 4000000 /dev/zero > '" + folder.file("big") + "'", limits);
  EXPECT_EQ(run.ending, BoundedRun::kFileSize);
  struct stat written {};
  ASSERT_EQ(stat(folder.file("big").c_str(), &written), 0);
  EXPECT_LE(written.st_size, 1 << 20);
  EXPECT_EQ(limit_words(run, limits, "the compiler"),
            "the compiler wrote a file larger than its limit of 1 MiB");
}

TEST(BoundedRun, TheCompilerOnDevZeroStopsAtTheMemoryLimit) {
  wobble::testing::TemporaryFolder folder;
  std::ofstream(folder.file("zero.cpp")) << "#include \"/dev/zero\"\nint x;\n";
  ProcessLimits limits;
  limits.wall_seconds = 60;
  limits.memory_bytes = 512LL << 20;
  const auto start = Clock::now();
  const BoundedRun run =
      run_bounded({"g++", "-c", folder.file("zero.cpp"), "-o", folder.file("zero.o")}, limits,
                  64 << 10, -1, nullptr);
  EXPECT_EQ(run.ending, BoundedRun::kMemory) << run.messages;
  EXPECT_LT(seconds_since(start), 20.0);  // 0.4 s on the 2-core development machine
  EXPECT_EQ(limit_words(run, limits, "the compiler"),
            "the compiler passed its memory limit of 512 MiB");
}

TEST(BoundedRun, AQuotedSourceLineIsNotTheCompilerRunningOutOfMemory) {
  ProcessLimits limits;
  limits.memory_bytes = 512LL << 20;
  const BoundedRun run = run_shell(
      "printf 'a.cpp:12:3: error: x\\n   12 |   // out of memory\\n      |   ^\\n' >&2; exit 1",
      limits);
  EXPECT_EQ(run.ending, BoundedRun::kExited);
  EXPECT_EQ(run.exit_code, 1);
}

TEST(BoundedRun, MessagesAreKeptToTheLimitAndCounted) {
  const BoundedRun run = run_shell("yes error | head -c 1000000 >&2", ProcessLimits{}, 64 << 10);
  EXPECT_EQ(run.ending, BoundedRun::kExited);
  EXPECT_EQ(run.messages.size(), 64u << 10);
  EXPECT_EQ(run.messages_bytes, 1000000);
  EXPECT_EQ(run.messages.substr(0, 12), "error\nerror\n");
}

TEST(BoundedRun, AProgramThatIsNotThereIsNotStarted) {
  const BoundedRun run =
      run_bounded({"wobble-no-such-program"}, ProcessLimits{}, 1024, -1, nullptr);
  EXPECT_EQ(run.ending, BoundedRun::kNotStarted);
  EXPECT_NE(run.messages.find("No such file or directory"), std::string::npos) << run.messages;
}

TEST(BoundedRun, AStopRequestEndsTheGroup) {
  const Marker marker;
  static volatile std::sig_atomic_t stop = 0;
  stop = 0;
  std::thread stopper([] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    stop = SIGTERM;
  });
  const BoundedRun run =
      run_bounded({"sh", "-c", "sleep 30 & sleep 31"}, ProcessLimits{}, 1024, -1, &stop);
  stopper.join();
  EXPECT_EQ(run.ending, BoundedRun::kStopped);
  EXPECT_TRUE(marker.all_gone());
}

TEST(EndGroupOnTermination, SigtermToTheCallerEndsTheGroupFirst) {
  const Marker marker;
  const pid_t caller = fork();
  ASSERT_GE(caller, 0);
  if (caller == 0) {
    const pid_t group =
        spawn_bounded({"sh", "-c", "sleep 30 & sleep 31"}, ProcessLimits{}, ChildStreams{});
    if (group < 0) _exit(10);
    const EndGroupOnTermination end_on_termination(group, 0.0);
    raise(SIGTERM);
    _exit(11);  // not reached: SIGTERM still ends the caller
  }
  int status = 0;
  ASSERT_EQ(waitpid(caller, &status, 0), caller);
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit status " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_TRUE(marker.all_gone()) << "the group outlived the caller";
}

TEST(EndGroupOnTermination, WithAGraceTheGroupMayCleanUpFirst) {
  // The group's leader removes its file on SIGTERM (as the checker script removes its
  // temporary folder); the caller waits for it before ending.
  wobble::testing::TemporaryFolder folder;
  const std::string file = folder.file("work");
  const pid_t caller = fork();
  ASSERT_GE(caller, 0);
  if (caller == 0) {
    // The trap first: the file says the group is ready for the signal.
    const std::string script = "trap \"sleep 0.3; rm -f '" + file + "'; exit 0\" TERM; touch '" +
                               file + "'; while :; do sleep 0.05; done";
    const pid_t group = spawn_bounded({"sh", "-c", script}, ProcessLimits{}, ChildStreams{});
    if (group < 0) _exit(10);
    const EndGroupOnTermination end_on_termination(group, 5.0);
    while (access(file.c_str(), F_OK) != 0)
      usleep(10000);
    raise(SIGTERM);
    _exit(11);
  }
  int status = 0;
  ASSERT_EQ(waitpid(caller, &status, 0), caller);
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit status " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_NE(access(file.c_str(), F_OK), 0) << "the group was killed before it removed its file";
}

TEST(SpawnBounded, TheLimitsAreInPlaceBeforeTheProgramRuns) {
  wobble::testing::TemporaryFolder folder;
  ProcessLimits limits;
  limits.memory_bytes = 300LL << 20;
  limits.file_bytes = 2 << 20;
  limits.cpu_seconds = 7;
  const std::string out = folder.file("limits");
  const pid_t child = spawn_bounded(
      {"sh", "-c",
       "{ ulimit -v; ulimit -f; ulimit -t; ulimit -c; ps -o pgid= -p $$; } > '" + out + "'"},
      limits, ChildStreams{});
  ASSERT_GT(child, 0);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  std::ifstream in(out);
  std::string memory, file, cpu, core, group;
  in >> memory >> file >> cpu >> core >> group;
  EXPECT_EQ(memory, std::to_string(300 << 10));  // KiB
  EXPECT_EQ(file, std::to_string(2 << 11));      // sh counts 512-byte blocks
  EXPECT_EQ(cpu, "7");
  EXPECT_EQ(core, "0");
  EXPECT_EQ(group, std::to_string(child)) << "expected a process group of its own";
}

TEST(SpawnBounded, AProgramThatIsNotThereIsENOENT) {
  errno = 0;
  EXPECT_EQ(spawn_bounded({"wobble-no-such-program"}, ProcessLimits{}, ChildStreams{}), -1);
  EXPECT_EQ(errno, ENOENT);
}

TEST(RunInChild, AForkInTheStudentsCodeLeavesNothingBehind) {
  const Marker marker;
  ChildLimits limits;
  limits.seconds = 5;
  const ChildOutcome outcome = run_in_child(
      [](std::string&) {
        // As a student's function that forks and returns: the child outlives the check.
        if (fork() == 0) {
          execl("/bin/sleep", "sleep", "30", static_cast<char*>(nullptr));
          _exit(127);
        }
        return true;
      },
      limits);
  EXPECT_EQ(outcome.kind, ChildOutcome::kAgreed);
  EXPECT_TRUE(marker.all_gone()) << "the student's forked child outlived the check";
}

}  // namespace

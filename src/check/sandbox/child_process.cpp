#include "child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <new>
#include <stdexcept>
#include <thread>

#include "bounded_process.h"

namespace {

// Exit codes the child uses to tell the parent how the check ended, beyond 0 and 1; they only
// count after the completion marker below, so a student's own exit() is never misread.
constexpr int kCodeDiffered = 1;
constexpr int kCodeOutOfMemory = 93;
constexpr int kCodeThrew = 94;
const std::string kCompletedMarker = "done:";

void write_all(int fd, const std::string& text) {
  size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = write(fd, text.data() + written, text.size() - written);
    if (n <= 0) return;
    written += static_cast<size_t>(n);
  }
}

[[noreturn]] void run_child(const ChildCheck& check, const ChildLimits& limits, int result_fd,
                            int output_fd) {
  dup2(output_fd, STDOUT_FILENO);
  dup2(output_fd, STDERR_FILENO);
  // Its own process group, so that whatever it starts (a fork in the student's code) ends with
  // it; its CPU time as long as its wall clock; a student's code printing in a loop must not
  // fill the disk: past 16 MiB a write just fails (SIGXFSZ ignored).
  ProcessLimits bounds;
  bounds.cpu_seconds = limits.seconds;
  bounds.memory_bytes = limits.memory_bytes;
  bounds.file_bytes = 16 << 20;
  enter_bounds(bounds);
  signal(SIGXFSZ, SIG_IGN);

  int code = 0;
  std::string text;
  try {
    code = check(text) ? 0 : kCodeDiffered;
  } catch (const std::bad_alloc&) {
    code = kCodeOutOfMemory;
  } catch (const std::exception& error) {
    code = kCodeThrew;
    text = error.what();
  } catch (...) {
    code = kCodeThrew;
    text = "an exception that is not a std::exception";
  }
  // The marker says the check ran to its end: a student's exit(0) writes nothing, and must not
  // read as agreement.
  write_all(result_fd, kCompletedMarker + text);
  std::fflush(stdout);
  std::fflush(stderr);
  _exit(code);
}

// The last non-empty line of what the child printed, at most 200 characters.
std::string last_line(std::FILE* output) {
  std::fflush(output);
  std::rewind(output);
  std::string all;
  char buffer[4096];
  for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, output)) > 0;) {
    all.append(buffer, n);
    if (all.size() > 65536) all.erase(0, all.size() - 65536);
  }
  while (!all.empty() && (all.back() == '\n' || all.back() == '\r' || all.back() == ' '))
    all.pop_back();
  const size_t start = all.find_last_of('\n');
  std::string line = start == std::string::npos ? all : all.substr(start + 1);
  // An assertion's line starts with the program, file and function, which say nothing to a
  // student; the condition that failed does.
  const size_t assertion = line.find("Assertion `");
  if (assertion != std::string::npos) line = line.substr(assertion);
  if (line.size() > 200) line = line.substr(0, 200) + "...";
  return line;
}

}  // namespace

std::string signal_name(int signal_number) {
  switch (signal_number) {
    case SIGSEGV:
      return "SIGSEGV";
    case SIGABRT:
      return "SIGABRT";
    case SIGFPE:
      return "SIGFPE";
    case SIGILL:
      return "SIGILL";
    case SIGBUS:
      return "SIGBUS";
    case SIGKILL:
      return "SIGKILL";
    case SIGTERM:
      return "SIGTERM";
    case SIGTRAP:
      return "SIGTRAP";
    case SIGPIPE:
      return "SIGPIPE";
    case SIGXCPU:
      return "SIGXCPU";
    default:
      return "signal " + std::to_string(signal_number);
  }
}

ChildOutcome run_in_child(const ChildCheck& check, const ChildLimits& limits) {
  ChildOutcome outcome;
  int result_pipe[2];
  std::FILE* output = std::tmpfile();
  if (!output || pipe(result_pipe) != 0) throw std::runtime_error("cannot create a pipe or file");
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t child = fork();
  if (child < 0) throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
  if (child == 0) {
    close(result_pipe[0]);
    run_child(check, limits, result_pipe[1], fileno(output));
  }
  close(result_pipe[1]);
  setpgid(child, child);  // also here, so the group exists before any kill below

  // Read the child's result until it ends or the time is up. A process that the student's
  // code forked may hold the pipe open after the child has ended: once the child is reaped,
  // only what is in the pipe already is read. (A child that closed the pipe itself and went on
  // looping is still a time-out.)
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration<double>(limits.seconds);
  fcntl(result_pipe[0], F_SETFL, fcntl(result_pipe[0], F_GETFL) | O_NONBLOCK);
  const auto read_available = [&]() {  // false once the pipe is closed
    char buffer[4096];
    for (;;) {
      const ssize_t n = read(result_pipe[0], buffer, sizeof buffer);
      if (n > 0)
        outcome.text.append(buffer, static_cast<size_t>(n));
      else if (n == 0)
        return false;
      else if (errno != EINTR)
        return errno == EAGAIN || errno == EWOULDBLOCK;
    }
  };
  int status = 0;
  bool pipe_open = true, reaped = false, timed_out = false;
  while (!reaped) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) {
      timed_out = true;
      break;
    }
    if (pipe_open) {
      pollfd wait_for{result_pipe[0], POLLIN, 0};
      if (poll(&wait_for, 1, static_cast<int>(std::min<long long>(left, 20))) > 0)
        pipe_open = read_available();
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    reaped = waitpid(child, &status, WNOHANG) == child;
  }
  if (reaped && pipe_open) read_available();  // what it wrote before it ended
  close(result_pipe[0]);

  const bool completed = outcome.text.rfind(kCompletedMarker, 0) == 0;
  if (completed) outcome.text.erase(0, kCompletedMarker.size());

  // Whatever the check started and left in its group (a student's fork) ends with it.
  kill_group(child, timed_out);
  if (timed_out) {
    waitpid(child, &status, 0);
    outcome.kind = ChildOutcome::kTimedOut;
  } else if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU) {
    outcome.kind = ChildOutcome::kTimedOut;  // its CPU time ran out first
  } else if (WIFSIGNALED(status)) {
    outcome.kind = ChildOutcome::kCrashed;
    outcome.signal_name = signal_name(WTERMSIG(status));
  } else if (!completed) {
    outcome.kind = ChildOutcome::kExited;
  } else if (WEXITSTATUS(status) == 0) {
    outcome.kind = ChildOutcome::kAgreed;
  } else if (WEXITSTATUS(status) == kCodeDiffered) {
    outcome.kind = ChildOutcome::kDiffered;
  } else if (WEXITSTATUS(status) == kCodeOutOfMemory) {
    outcome.kind = ChildOutcome::kOutOfMemory;
  } else if (WEXITSTATUS(status) == kCodeThrew) {
    outcome.kind = ChildOutcome::kThrew;
  } else {
    outcome.kind = ChildOutcome::kExited;
  }
  outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 0;
  outcome.output_tail = last_line(output);
  std::fclose(output);
  // An uncaught bad_alloc (thrown through a noexcept function) ends in std::terminate.
  if (outcome.kind == ChildOutcome::kCrashed &&
      outcome.output_tail.find("std::bad_alloc") != std::string::npos)
    outcome.kind = ChildOutcome::kOutOfMemory;
  return outcome;
}

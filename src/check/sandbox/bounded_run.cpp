#include "bounded_run.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>

namespace {

using Clock = std::chrono::steady_clock;

// What a program says when a limit stopped it, line by line over everything it writes (the
// kept part and the dropped part), so that the limit is named even after a long cascade.
class LimitWords {
 public:
  void feed(const char* text, std::size_t size) {
    for (std::size_t i = 0; i < size; ++i) {
      if (text[i] == '\n') {
        end_line();
      } else if (line_.size() < 4096) {
        line_ += text[i];
      }
    }
  }
  void end_line() {
    // GCC quotes the student's source as "   12 | code" and marks it with "      | ^~~": a
    // comment there that says "out of memory" says nothing about the compiler.
    const std::size_t first = line_.find_first_not_of(" 0123456789");
    const bool quoted = first != std::string::npos && line_[first] == '|';
    if (!quoted) {
      for (const char* words :
           {"out of memory", "memory exhausted", "Cannot allocate memory", "std::bad_alloc"})
        memory = memory || line_.find(words) != std::string::npos;
      cpu = cpu || line_.find("CPU time limit exceeded") != std::string::npos;
      for (const char* words : {"File size limit exceeded", "File too large"})
        file = file || line_.find(words) != std::string::npos;
    }
    line_.clear();
  }
  bool memory = false, cpu = false, file = false;

 private:
  std::string line_;
};

std::string seconds_words(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", seconds);
  return text;
}

double cpu_seconds_of(const rusage& usage) {
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

}  // namespace

BoundedRun run_bounded(const std::vector<std::string>& arguments, const ProcessLimits& limits,
                       std::size_t messages_limit, int copy_fd,
                       const volatile std::sig_atomic_t* stop) {
  BoundedRun run;
  int messages_pipe[2];
  if (pipe2(messages_pipe, O_CLOEXEC) != 0) {
    run.ending = BoundedRun::kNotStarted;
    run.messages = std::string("cannot make a pipe: ") + std::strerror(errno);
    return run;
  }
  // It gets SIGTERM should this process be killed outright (SIGKILL gives no chance to clean up).
  const pid_t child =
      spawn_bounded(arguments, limits, ChildStreams{-1, -1, messages_pipe[1]}, true);
  const int spawn_error = errno;
  close(messages_pipe[1]);
  if (child < 0) {
    close(messages_pipe[0]);
    run.ending = BoundedRun::kNotStarted;
    run.messages = "cannot run " + (arguments.empty() ? std::string() : arguments[0]) + ": " +
                   std::strerror(spawn_error);
    return run;
  }
  int messages_fd = messages_pipe[0];
  fcntl(messages_fd, F_SETFL, fcntl(messages_fd, F_GETFL) | O_NONBLOCK);

  LimitWords said;
  const auto take = [&](const char* text, std::size_t size) {
    said.feed(text, size);
    run.messages_bytes += static_cast<long long>(size);
    const std::size_t kept =
        std::min(size, messages_limit - std::min(messages_limit, run.messages.size()));
    if (kept == 0) return;
    run.messages.append(text, kept);
    for (std::size_t written = 0; copy_fd >= 0 && written < kept;) {
      const ssize_t n = write(copy_fd, text + written, kept - written);
      if (n <= 0 && errno != EINTR) break;
      if (n > 0) written += static_cast<std::size_t>(n);
    }
  };
  // Reads what is there now; false once the pipe is closed.
  const auto read_messages = [&]() {
    char buffer[65536];
    for (;;) {
      const ssize_t n = read(messages_fd, buffer, sizeof buffer);
      if (n > 0) {
        take(buffer, static_cast<std::size_t>(n));
      } else if (n == 0 || (errno != EINTR && errno != EAGAIN && errno != EWOULDBLOCK)) {
        return false;
      } else if (errno != EINTR) {
        return true;
      }
    }
  };

  const auto deadline = Clock::now() + std::chrono::duration<double>(limits.wall_seconds);
  int status = 0;
  rusage usage{};
  bool reaped = false;
  while (!reaped) {
    if (stop && *stop) {
      run.ending = BoundedRun::kStopped;
      break;
    }
    long long wait_milliseconds = 50;
    if (limits.wall_seconds > 0) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) {
        run.ending = BoundedRun::kWallClock;
        break;
      }
      wait_milliseconds = std::min<long long>(wait_milliseconds, left);
    }
    if (messages_fd >= 0) {
      pollfd wait_for{messages_fd, POLLIN, 0};
      if (poll(&wait_for, 1, static_cast<int>(wait_milliseconds)) > 0 && !read_messages()) {
        close(messages_fd);
        messages_fd = -1;
      }
    } else {
      const timespec pause{0, static_cast<long>(wait_milliseconds) * 1000000};
      nanosleep(&pause, nullptr);
    }
    reaped = wait4(child, &status, WNOHANG, &usage) == child;
  }
  // Whatever it started and left running in its group goes with it.
  kill_group(child, !reaped);
  if (!reaped) {
    while (wait4(child, &status, 0, &usage) < 0 && errno == EINTR) {
    }
  }
  if (messages_fd >= 0) {
    // Only what is already there: an orphan that left the group may hold the pipe open.
    read_messages();
    close(messages_fd);
  }
  said.end_line();
  if (run.ending != BoundedRun::kExited) return run;

  const bool failed = !WIFEXITED(status) || WEXITSTATUS(status) != 0;
  const int signal_number = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  if (limits.cpu_seconds > 0 &&
      (signal_number == SIGXCPU || (failed && said.cpu) ||
       (signal_number == SIGKILL && cpu_seconds_of(usage) >= limits.cpu_seconds))) {
    run.ending = BoundedRun::kCpuTime;
  } else if (limits.file_bytes > 0 && (signal_number == SIGXFSZ || (failed && said.file))) {
    run.ending = BoundedRun::kFileSize;
  } else if (limits.memory_bytes > 0 && failed && said.memory) {
    run.ending = BoundedRun::kMemory;
  } else if (signal_number != 0) {
    run.ending = BoundedRun::kSignaled;
    run.signal_number = signal_number;
  } else {
    run.exit_code = WEXITSTATUS(status);
  }
  return run;
}

std::string limit_words(const BoundedRun& run, const ProcessLimits& limits,
                        const std::string& name) {
  switch (run.ending) {
    case BoundedRun::kWallClock:
      return name + " took longer than its " + seconds_words(limits.wall_seconds) + " s limit";
    case BoundedRun::kCpuTime:
      return name + " passed its CPU time limit of " + seconds_words(limits.cpu_seconds) + " s";
    case BoundedRun::kMemory:
      return name + " passed its memory limit of " + size_words(limits.memory_bytes);
    case BoundedRun::kFileSize:
      return name + " wrote a file larger than its limit of " + size_words(limits.file_bytes);
    default:
      return "";
  }
}

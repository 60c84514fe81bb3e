#ifndef WOBBLE_CHECK_BOUNDED_RUN_H
#define WOBBLE_CHECK_BOUNDED_RUN_H

#include <csignal>
#include <cstddef>
#include <string>
#include <vector>

#include "bounded_process.h"

// Runs one program within limits and waits for it: the loop of the launcher
// (bounded_main.cpp) that scripts/check-assignment.sh puts in front of every compiler and
// checker. Which limit ended it is told apart here, so the launcher can say so in one line.

struct BoundedRun {
  enum Ending {
    kExited,      // it ended by itself with exit_code
    kSignaled,    // a signal that no limit explains ended it (signal_number)
    kWallClock,   // still running after ProcessLimits::wall_seconds: killed
    kCpuTime,     // it passed ProcessLimits::cpu_seconds (SIGXCPU, or its messages say so)
    kMemory,      // an allocation failed under ProcessLimits::memory_bytes (its messages say so)
    kFileSize,    // a file it wrote reached ProcessLimits::file_bytes (SIGXFSZ, "File too large")
    kStopped,     // *stop became non-zero (a signal to the caller): killed
    kNotStarted,  // it could not be started; `messages` says why
  };
  Ending ending = kExited;
  int exit_code = 0;
  int signal_number = 0;
  std::string messages;          // the first messages_limit bytes it wrote to stderr
  long long messages_bytes = 0;  // all the bytes it wrote to stderr
};

// Runs `arguments` within `limits` (spawn_bounded), its stdin and stdout this process's, its
// stderr through a pipe: the first `messages_limit` bytes are kept (and copied to `copy_fd` as
// they come, when it is not -1), the rest only counted and scanned for what a limit makes a
// compiler say, so that an error cascade cannot fill a log. Waits until the program ends, the
// wall clock runs out, or `stop` (when not null) becomes non-zero; then SIGKILL to whatever is
// left of its process group, and it is reaped. It gets SIGTERM should the calling thread end
// first (PR_SET_PDEATHSIG): call it on a thread that lives until it returns. What left the group
// (setsid) is not found here: a launcher that adopts orphans ends them with end_every_child.
BoundedRun run_bounded(const std::vector<std::string>& arguments, const ProcessLimits& limits,
                       std::size_t messages_limit, int copy_fd,
                       const volatile std::sig_atomic_t* stop);

// What ended `run`, in words, with `name` as the subject: "the compiler passed its memory
// limit of 2 GiB", "the compiler took longer than its 120 s limit"; "" when no limit did.
std::string limit_words(const BoundedRun& run, const ProcessLimits& limits,
                        const std::string& name);

#endif

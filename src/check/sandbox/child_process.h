#ifndef WOBBLE_CHECK_CHILD_PROCESS_H
#define WOBBLE_CHECK_CHILD_PROCESS_H

#include <functional>
#include <string>

// Runs one check in a child process (fork), so that whatever the student's code does there
// (crash, loop forever, allocate without end, print, call exit, fork) the checker itself goes
// on. The child is bounded as every process with a student's code is (bounded_process.h): a
// process group of its own, killed as a whole when the check ends, however it ends.

struct ChildLimits {
  double seconds = 10;                 // wall clock and CPU time; the child is killed past them
  long long memory_bytes = 2LL << 30;  // address space (RLIMIT_AS) of the child
};

struct ChildOutcome {
  enum Kind {
    kAgreed,       // the check returned true (its payload in `text`)
    kDiffered,     // the check returned false (its payload, what differs, in `text`)
    kCrashed,      // killed by a signal (`signal_name`, e.g. "SIGSEGV")
    kTimedOut,     // still running after ChildLimits::seconds
    kOutOfMemory,  // an allocation failed under ChildLimits::memory_bytes
    kThrew,        // an exception other than std::bad_alloc (`text` is its what())
    kExited,       // the process ended itself with exit(`exit_code`)
  };
  Kind kind = kAgreed;
  std::string text;
  std::string signal_name;
  int exit_code = 0;
  std::string output_tail;  // the last line the child wrote to stdout or stderr, if any
};

// Runs `check` in a child with those limits. `check` returns true when the student's function
// agrees with the reference and sets `payload` to what the parent should know (what differs,
// notes), which comes back in ChildOutcome::text. The child's stdout and stderr go to a
// temporary file (at most 16 MiB), not to the checker's terminal.
using ChildCheck = std::function<bool(std::string& payload)>;
ChildOutcome run_in_child(const ChildCheck& check, const ChildLimits& limits);

// "SIGSEGV" for SIGSEGV, and so on; "signal N" for one without a name.
std::string signal_name(int signal_number);

#endif

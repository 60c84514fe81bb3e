#ifndef WOBBLE_CHECK_BOUNDED_PROCESS_H
#define WOBBLE_CHECK_BOUNDED_PROCESS_H

#include <sys/types.h>

#include <string>
#include <vector>

// The one way Wobble starts a process that compiles or runs a student's code (g++ on a
// submission, a checker with the student's functions linked in, the viewer's step server, each
// check of a function): in a process group of its own, so that it and everything it starts can
// be ended together with one kill(-group, SIGKILL), and within limits the kernel enforces.
//
// Who uses it: bounded_run.h (the launcher, bounded_main.cpp, that scripts/check-assignment.sh
// puts in front of every compiler and checker it runs), child_process.cpp (each check),
// src/app/student/student_step.cpp (the step server) and src/app/student/student_server.cpp (the
// script itself, from wobble --student).

// Limits of one process and each process it starts (they inherit them). 0: no limit.
struct ProcessLimits {
  double wall_seconds = 0;     // wall clock; enforced by whoever waits (run_bounded), not here
  double cpu_seconds = 0;      // RLIMIT_CPU: SIGXCPU at this many seconds, SIGKILL a second later
  long long memory_bytes = 0;  // RLIMIT_AS: an allocation past it fails (std::bad_alloc)
  long long file_bytes = 0;    // RLIMIT_FSIZE: no file it writes grows past it (SIGXFSZ)
};

// In a child, between fork and exec (or before it runs a check): a process group of its own,
// `limits` (but the wall clock), no core files, default handling of every signal and none
// blocked. Only async-signal-safe calls, so a child of a program with threads may call it.
// Returns false when a limit could not be set (a limit above the hard limit this process has).
bool enter_bounds(const ProcessLimits& limits);

// Where the child's stdin, stdout and stderr come from: a file descriptor, or -1 for this
// process's own.
struct ChildStreams {
  int in = -1;
  int out = -1;
  int err = -1;
};

// Starts `arguments` (arguments[0] looked up in PATH when it has no '/') in a process group of
// its own, whose id is the pid returned, within `limits` (enter_bounds). With `die_with_parent`
// the child is sent SIGTERM when the thread that started it ends (PR_SET_PDEATHSIG): only for a
// caller that waits for it on the same thread. Between fork and exec the child makes only
// async-signal-safe calls. Returns -1 with errno set when it cannot be started (no such
// program: ENOENT).
pid_t spawn_bounded(const std::vector<std::string>& arguments, const ProcessLimits& limits,
                    const ChildStreams& streams, bool die_with_parent = false);

// SIGKILL to every process in the process group `group`; with `leader_unreaped`, also to the
// process `group` itself, which must then be a child of this process not reaped yet (a leader
// that left its group is still ended, and a reaped pid may already be another process's).
// Reaps nothing.
void kill_group(pid_t group, bool leader_unreaped);

// Makes this process a subreaper (PR_SET_CHILD_SUBREAPER): a process that its descendants
// leave behind (a student's double fork, setsid and all) becomes this process's child instead
// of init's, so end_every_child can end it. False where the kernel does not offer it.
bool adopt_orphans();

// SIGKILL to every child of this process, found in /proc, and reaps them, until this process
// has no child left (or 5 s have passed): what it adopted, and what those leave behind in turn.
// Only for a process whose every child is bounded (the launcher). Returns how many it ended.
int end_every_child();

// While an object lives, SIGTERM, SIGINT and SIGHUP to this program first end the process
// group `group` (a child of this process and the group's leader): with a grace, SIGTERM to the
// group, up to `grace_seconds` for the leader to end by itself (the checker script removes its
// temporary folder), then SIGKILL to the group and to the leader if it still runs; with none,
// SIGKILL to the group at once (its leader may have been reaped already). Then the signal does what
// it did before (the previous handler, or ending the program). A signal this program ignores stays
// ignored. At most 8 groups at once; objects may live on any thread.
class EndGroupOnTermination {
 public:
  EndGroupOnTermination(pid_t group, double grace_seconds);
  ~EndGroupOnTermination();
  EndGroupOnTermination(const EndGroupOnTermination&) = delete;
  EndGroupOnTermination& operator=(const EndGroupOnTermination&) = delete;

 private:
  int slot_ = -1;
};

// "2 GiB", "300 MiB", "64 KiB": a size as the limits are set.
std::string size_words(long long bytes);

#endif

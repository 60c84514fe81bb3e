// The launcher that scripts/check-assignment.sh puts in front of every compiler and checker it
// runs (build_checkers.sh compiles it into its cache as bin/bounded-KEY):
//
//   bounded [--name TEXT] [--seconds S] [--cpu-seconds S] [--memory-mib M] [--file-mib F]
//           [--messages-kib K] -- COMMAND [ARGUMENT...]
//
// runs COMMAND in a process group of its own within the limits (wall clock S seconds, each
// process's CPU time, address space and file size; 0 or left out: none; --cpu-seconds is
// --seconds unless given) and keeps the first K KiB (default 64) of what it writes to stderr,
// copied to this stderr. When COMMAND ends, is killed at a limit, or this launcher gets
// SIGTERM, SIGINT or SIGHUP (or the process that started it ends), whatever is left of COMMAND's
// group is killed, and so is every orphan it left behind (the launcher is their subreaper), so
// nothing outlives it.
//
// Exit status: COMMAND's; when a signal ended COMMAND, the launcher ends by the same signal; 124
// when a limit ended it, after one line on stderr, "bounded: NAME passed its memory limit of
// 2 GiB" (or "took longer than its S s limit", "passed its CPU time limit", "wrote a file larger
// than its limit"); 127 when COMMAND cannot start; 2 for a usage error. Stopped by a signal, it
// ends by that signal once everything is gone.
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bounded_run.h"

namespace {

volatile std::sig_atomic_t stop_signal = 0;

extern "C" void note_stop(int signal_number) {
  stop_signal = signal_number;
}

[[noreturn]] void bad_usage(const std::string& why) {
  std::fprintf(stderr, "bounded: %s\n", why.c_str());
  std::exit(2);
}

double number_of(const char* option, const char* text) {
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end || !(value >= 0))
    bad_usage(std::string(option) + ": expected a number >= 0, got '" + text + "'");
  return value;
}

// Ends this process by `signal_number`, as the command was, or as this launcher was told to.
[[noreturn]] void end_by(int signal_number) {
  std::fflush(stderr);
  signal(signal_number, SIG_DFL);
  sigset_t just_that;
  sigemptyset(&just_that);
  sigaddset(&just_that, signal_number);
  sigprocmask(SIG_UNBLOCK, &just_that, nullptr);
  raise(signal_number);
  std::_Exit(128 + signal_number);  // a signal whose default is not to end a process
}

}  // namespace

int main(int argc, char** argv) {
  ProcessLimits limits;
  std::string name = "the command";
  std::size_t messages_limit = 64 << 10;
  double cpu_seconds = -1;
  int index = 1;
  for (; index < argc && std::strcmp(argv[index], "--") != 0; index += 2) {
    const std::string option = argv[index];
    if (index + 1 >= argc) bad_usage(option + " needs a value");
    const char* value = argv[index + 1];
    if (option == "--name")
      name = value;
    else if (option == "--seconds")
      limits.wall_seconds = number_of(argv[index], value);
    else if (option == "--cpu-seconds")
      cpu_seconds = number_of(argv[index], value);
    else if (option == "--memory-mib")
      limits.memory_bytes = static_cast<long long>(number_of(argv[index], value)) << 20;
    else if (option == "--file-mib")
      limits.file_bytes = static_cast<long long>(number_of(argv[index], value)) << 20;
    else if (option == "--messages-kib")
      messages_limit = static_cast<std::size_t>(number_of(argv[index], value)) << 10;
    else
      bad_usage("unknown option " + option);
  }
  if (index + 1 >= argc) bad_usage("expected -- COMMAND [ARGUMENT...]");
  limits.cpu_seconds = cpu_seconds >= 0 ? cpu_seconds : limits.wall_seconds;
  const std::vector<std::string> command(argv + index + 1, argv + argc);

  // The script that started this may be killed outright; then this launcher still cleans up.
  const pid_t parent = getppid();
  prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (getppid() != parent) stop_signal = SIGTERM;
  adopt_orphans();
  struct sigaction action {};
  action.sa_handler = note_stop;
  sigemptyset(&action.sa_mask);
  for (const int signal_number : {SIGTERM, SIGINT, SIGHUP}) {
    struct sigaction current {};
    sigaction(signal_number, nullptr, &current);
    // SIGINT stays ignored in a background job of a script: the script's trap sends SIGTERM.
    if (signal_number == SIGTERM || current.sa_handler != SIG_IGN)
      sigaction(signal_number, &action, nullptr);
  }
  const rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);  // a crash passed on by end_by leaves no core file

  const BoundedRun run = run_bounded(command, limits, messages_limit, STDERR_FILENO, &stop_signal);
  end_every_child();
  if (run.messages_bytes > static_cast<long long>(run.messages.size())) {
    std::fprintf(stderr, "[%lld more bytes of %s's messages left out]\n",
                 run.messages_bytes - static_cast<long long>(run.messages.size()), name.c_str());
  }
  if (stop_signal != 0) end_by(stop_signal);  // also when it came after the command ended
  switch (run.ending) {
    case BoundedRun::kNotStarted:
      std::fprintf(stderr, "bounded: %s\n", run.messages.c_str());
      return 127;
    case BoundedRun::kStopped:
      end_by(stop_signal);
    case BoundedRun::kSignaled:
      end_by(run.signal_number);
    case BoundedRun::kExited:
      return run.exit_code;
    default:
      std::fprintf(stderr, "bounded: %s\n", limit_words(run, limits, name).c_str());
      return 124;
  }
}

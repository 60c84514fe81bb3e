#include "bounded_process.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace {

long long monotonic_milliseconds() {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<long long>(now.tv_sec) * 1000 + now.tv_nsec / 1000000;
}

void sleep_milliseconds(long milliseconds) {
  timespec pause{milliseconds / 1000, (milliseconds % 1000) * 1000000};
  nanosleep(&pause, nullptr);
}

// Sets a limit, never above the hard limit this process already has (a checker run within the
// launcher's limits sets its checks' lower ones, never higher ones), so it cannot fail for that.
bool set_limit(int resource, rlim_t soft, rlim_t hard) {
  rlimit current{};
  if (getrlimit(resource, &current) != 0) return false;
  if (current.rlim_max != RLIM_INFINITY) {
    if (hard == RLIM_INFINITY || hard > current.rlim_max) hard = current.rlim_max;
    if (soft == RLIM_INFINITY || soft > current.rlim_max) soft = current.rlim_max;
  }
  const rlimit wanted{soft, hard};
  return setrlimit(resource, &wanted) == 0;
}

// The file `name` names when run as a command: itself when it has a '/', else the first
// executable of that name in PATH's folders; "" when there is none.
std::string find_program(const std::string& name) {
  if (name.find('/') != std::string::npos) return name;
  const char* path = std::getenv("PATH");
  const std::string folders = path ? path : "/usr/local/bin:/usr/bin:/bin";
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = folders.find(':', start);
    std::string folder = folders.substr(start, end == std::string::npos ? end : end - start);
    if (folder.empty()) folder = ".";
    const std::string candidate = folder + "/" + name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
    if (end == std::string::npos) return "";
    start = end + 1;
  }
}

// The parent process of `pid` from /proc/PID/stat, or -1. The command name in parentheses may
// hold spaces and parentheses itself, so the fields are counted from the last ')'.
pid_t parent_of(const char* pid_text) {
  char path[64];
  std::snprintf(path, sizeof path, "/proc/%s/stat", pid_text);
  const int fd = open(path, O_RDONLY | O_CLOEXEC);
  if (fd < 0) return -1;
  char text[1024];
  const ssize_t n = read(fd, text, sizeof text - 1);
  close(fd);
  if (n <= 0) return -1;
  text[n] = '\0';
  const char* after_name = std::strrchr(text, ')');
  if (!after_name) return -1;
  char state = 0;
  int parent = -1;
  if (std::sscanf(after_name + 1, " %c %d", &state, &parent) != 2) return -1;
  return parent;
}

std::vector<pid_t> children_of(pid_t parent) {
  std::vector<pid_t> children;
  DIR* proc = opendir("/proc");
  if (!proc) return children;
  while (const dirent* entry = readdir(proc)) {
    const char* name = entry->d_name;
    if (name[0] < '1' || name[0] > '9') continue;
    if (parent_of(name) == parent) children.push_back(static_cast<pid_t>(std::atoi(name)));
  }
  closedir(proc);
  return children;
}

// The groups that SIGTERM, SIGINT and SIGHUP end first (EndGroupOnTermination), read by the
// signal handler: lock-free atomics only.
constexpr int kGroupSlots = 8;
std::atomic<pid_t> registered_groups[kGroupSlots];
std::atomic<int> registered_grace_milliseconds[kGroupSlots];
constexpr int kEndingSignals[] = {SIGTERM, SIGINT, SIGHUP};
constexpr int kEndingSignalCount = 3;
struct sigaction previous_actions[kEndingSignalCount];
std::once_flag handler_installed;

// Async-signal-safe: kill, waitpid, clock_gettime and nanosleep only.
void end_registered_groups() {
  pid_t groups[kGroupSlots];
  long long until[kGroupSlots];
  const long long start = monotonic_milliseconds();
  for (int i = 0; i < kGroupSlots; ++i) {
    groups[i] = registered_groups[i].load();
    const int grace = registered_grace_milliseconds[i].load();
    until[i] = start + grace;
    if (groups[i] <= 0) continue;
    if (grace > 0) {
      kill(-groups[i], SIGTERM);
    } else {
      // Its leader may be reaped already, and its pid another process's: the group only.
      kill_group(groups[i], false);
      groups[i] = 0;
    }
  }
  for (bool waiting = true; waiting;) {
    waiting = false;
    for (int i = 0; i < kGroupSlots; ++i) {
      if (groups[i] <= 0) continue;
      // 0: the leader still runs. Reaped now (or not ours to wait for): the rest of its group
      // goes; still running at the end of its grace: all of it goes.
      const pid_t reaped = waitpid(groups[i], nullptr, WNOHANG);
      if (reaped == 0 && monotonic_milliseconds() < until[i]) {
        waiting = true;
        continue;
      }
      kill_group(groups[i], reaped == 0);
      groups[i] = 0;
    }
    if (waiting) sleep_milliseconds(10);
  }
}

extern "C" void end_groups_then_signal(int signal_number) {
  const int saved_errno = errno;
  end_registered_groups();
  for (int i = 0; i < kEndingSignalCount; ++i) {
    if (kEndingSignals[i] == signal_number) sigaction(signal_number, &previous_actions[i], nullptr);
  }
  errno = saved_errno;
  // Blocked until this handler returns; then the previous action takes it (Wobble's removal
  // of a half-written file, or the end of the program).
  raise(signal_number);
}

void install_handler() {
  struct sigaction action {};
  action.sa_handler = end_groups_then_signal;
  sigemptyset(&action.sa_mask);
  for (int i = 0; i < kEndingSignalCount; ++i) {
    sigaction(kEndingSignals[i], nullptr, &previous_actions[i]);
    // A signal the parent told us to ignore (nohup, a background job) stays ignored.
    if (previous_actions[i].sa_handler != SIG_IGN) sigaction(kEndingSignals[i], &action, nullptr);
  }
}

}  // namespace

bool enter_bounds(const ProcessLimits& limits) {
  setpgid(0, 0);
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  sigemptyset(&default_action.sa_mask);
  for (int signal_number = 1; signal_number < NSIG; ++signal_number) {
    if (signal_number != SIGKILL && signal_number != SIGSTOP)
      sigaction(signal_number, &default_action, nullptr);
  }
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  bool set = set_limit(RLIMIT_CORE, 0, 0);
  if (limits.cpu_seconds > 0) {
    // SIGXCPU at the limit; SIGKILL a second later for a process that ignores SIGXCPU.
    const auto seconds = static_cast<rlim_t>(std::ceil(limits.cpu_seconds));
    set = set_limit(RLIMIT_CPU, seconds, seconds + 1) && set;
  }
  if (limits.memory_bytes > 0) {
    const auto bytes = static_cast<rlim_t>(limits.memory_bytes);
    set = set_limit(RLIMIT_AS, bytes, bytes) && set;
  }
  if (limits.file_bytes > 0) {
    const auto bytes = static_cast<rlim_t>(limits.file_bytes);
    set = set_limit(RLIMIT_FSIZE, bytes, bytes) && set;
  }
  return set;
}

pid_t spawn_bounded(const std::vector<std::string>& arguments, const ProcessLimits& limits,
                    const ChildStreams& streams, bool die_with_parent) {
  if (arguments.empty()) {
    errno = EINVAL;
    return -1;
  }
  // Everything that allocates happens here, before the fork.
  const std::string program = find_program(arguments[0]);
  if (program.empty()) {
    errno = ENOENT;
    return -1;
  }
  std::vector<char*> argv;
  for (const std::string& argument : arguments)
    argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  // The child writes its errno here when it cannot exec; a successful exec closes the pipe.
  int exec_status[2];
  if (pipe2(exec_status, O_CLOEXEC) != 0) return -1;
  const pid_t parent = getpid();
  const pid_t child = fork();
  if (child == 0) {
    close(exec_status[0]);
    if (die_with_parent) {
      prctl(PR_SET_PDEATHSIG, SIGTERM);
      if (getppid() != parent) _exit(127);  // the parent ended before prctl
    }
    const int from[3] = {streams.in, streams.out, streams.err};
    for (int target = 0; target < 3; ++target) {
      if (from[target] < 0) continue;
      if (from[target] == target)
        fcntl(target, F_SETFD, 0);  // keep it open across exec
      else
        dup2(from[target], target);
    }
    enter_bounds(limits);
    execv(program.c_str(), argv.data());
    const int error = errno;
    ssize_t ignored = write(exec_status[1], &error, sizeof error);
    (void)ignored;
    _exit(127);
  }
  const int fork_error = errno;
  close(exec_status[1]);
  if (child < 0) {
    close(exec_status[0]);
    errno = fork_error;
    return -1;
  }
  setpgid(child, child);  // also here, so the group exists before the caller's first kill
  int child_error = 0;
  ssize_t n;
  while ((n = read(exec_status[0], &child_error, sizeof child_error)) < 0 && errno == EINTR) {
  }
  close(exec_status[0]);
  if (n == static_cast<ssize_t>(sizeof child_error)) {
    while (waitpid(child, nullptr, 0) < 0 && errno == EINTR) {
    }
    errno = child_error;
    return -1;
  }
  return child;
}

void kill_group(pid_t group, bool leader_unreaped) {
  if (group <= 0) return;
  kill(-group, SIGKILL);
  if (leader_unreaped) kill(group, SIGKILL);
}

bool adopt_orphans() {
  return prctl(PR_SET_CHILD_SUBREAPER, 1) == 0;
}

int end_every_child() {
  const pid_t self = getpid();
  const long long give_up = monotonic_milliseconds() + 5000;
  int reaped_count = 0;
  for (;;) {
    for (const pid_t child : children_of(self))
      kill(child, SIGKILL);
    const pid_t reaped = waitpid(-1, nullptr, WNOHANG);
    if (reaped > 0) {
      ++reaped_count;
      continue;
    }
    if (reaped < 0 && errno == ECHILD) break;
    if (monotonic_milliseconds() > give_up) break;
    sleep_milliseconds(1);
  }
  return reaped_count;
}

EndGroupOnTermination::EndGroupOnTermination(pid_t group, double grace_seconds) {
  if (group <= 0) return;
  std::call_once(handler_installed, install_handler);
  for (int i = 0; i < kGroupSlots; ++i) {
    // Claimed with -1 (the handler passes over it) until its grace is in place.
    pid_t empty = 0;
    if (registered_groups[i].compare_exchange_strong(empty, -1)) {
      registered_grace_milliseconds[i].store(static_cast<int>(grace_seconds * 1000));
      registered_groups[i].store(group);
      slot_ = i;
      return;
    }
  }
}

EndGroupOnTermination::~EndGroupOnTermination() {
  if (slot_ >= 0) registered_groups[slot_].store(0);
}

std::string size_words(long long bytes) {
  const char* units[] = {"GiB", "MiB", "KiB"};
  const long long sizes[] = {1LL << 30, 1LL << 20, 1LL << 10};
  for (int i = 0; i < 3; ++i) {
    if (bytes >= sizes[i] && bytes % sizes[i] == 0)
      return std::to_string(bytes / sizes[i]) + " " + units[i];
  }
  return std::to_string(bytes) + " bytes";
}

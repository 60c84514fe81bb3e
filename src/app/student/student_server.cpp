#include "app/student/student_server.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>
#include <vector>

#include "check/sandbox/bounded_process.h"
#include "sim/input_error.h"

namespace wobble {

namespace {

// How long the script may take to clean up (end its compilers, remove its temporary folder)
// when wobble is stopped by a signal during the build, before its whole group is killed.
constexpr double kScriptGraceSeconds = 5.0;

// The script's output (stdout and stderr together) and its exit status, or -1 with errno set
// when it could not be started. It runs in a process group of its own (bounded_process.h): a
// SIGTERM, SIGINT or SIGHUP to wobble meanwhile passes on to the script, which ends its
// compilers and removes its temporary folder before wobble ends, and the script gets SIGTERM
// if wobble is killed outright.
int run_script(const std::vector<std::string>& arguments, std::string& output) {
  int pipe_ends[2];
  if (pipe2(pipe_ends, O_CLOEXEC) != 0) return -1;
  const int nothing = open("/dev/null", O_RDONLY | O_CLOEXEC);
  const pid_t child = spawn_bounded(arguments, ProcessLimits{},
                                    ChildStreams{nothing, pipe_ends[1], pipe_ends[1]}, true);
  const int spawn_error = errno;
  if (nothing >= 0) close(nothing);
  close(pipe_ends[1]);
  if (child < 0) {
    close(pipe_ends[0]);
    errno = spawn_error;
    return -1;
  }
  const EndGroupOnTermination end_on_termination(child, kScriptGraceSeconds);
  char buffer[4096];
  for (;;) {
    const ssize_t got = read(pipe_ends[0], buffer, sizeof(buffer));
    if (got > 0) {
      output.append(buffer, static_cast<std::size_t>(got));
    } else if (got == 0 || errno != EINTR) {
      break;
    }
  }
  close(pipe_ends[0]);
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  kill_group(child, false);  // anything of the script's still in its group
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty()) lines.push_back(line);
  }
  return lines;
}

}  // namespace

std::string build_student_step_server(const std::string& folder) {
  const std::string script = std::string(WOBBLE_SOURCE_DIR) + "/scripts/check-assignment.sh";
  std::string output;
  const int status = run_script({"bash", script, "--build-step-server", folder}, output);
  const std::vector<std::string> lines = lines_of(output);
  if (status == 0 && !lines.empty()) return lines.back();
  if (status < 0) throw InputError("--student: cannot run " + script + ": " + std::strerror(errno));
  // The script explains itself on one line (a missing file, the compiler's first error).
  const std::string why = lines.empty() ? "exit status " + std::to_string(status) : lines.front();
  throw InputError("--student " + folder + ": " + why);
}

}  // namespace wobble

#include "student_server.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>
#include <vector>

#include "sim/input_error.h"

extern char** environ;

namespace wobble {

namespace {

// The script's output (stdout and stderr together) and its exit status, or -1 when it could not
// be started.
int run_script(const std::vector<std::string>& arguments, std::string& output) {
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) return -1;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_ends[0]);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  std::vector<char*> argv;
  for (const std::string& argument : arguments)
    argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  pid_t child = -1;
  const int spawned = posix_spawnp(&child, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_ends[1]);
  if (spawned != 0) {
    close(pipe_ends[0]);
    return -1;
  }
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

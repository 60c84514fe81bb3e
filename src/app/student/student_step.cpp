#include "app/student/student_step.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

#include "app/student/step_messages.h"
#include "check/sandbox/bounded_process.h"
#include "check/step_server/step_protocol.h"

namespace wobble {
namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string signal_words(int signal_number) {
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 32))
  if (const char* abbreviation = sigabbrev_np(signal_number))
    return std::string("SIG") + abbreviation;
#endif
  return "signal " + std::to_string(signal_number);
}

// The server's limits, set before its first instruction (the student's static initializers
// run before its main): the address space it also sets itself (2 GiB, or
// WOBBLE_STEP_SERVER_MEMORY_MIB), and 64 MiB for any file the student's code writes. No CPU
// limit: it serves every step while the viewer runs, each within seconds_per_step.
ProcessLimits server_limits() {
  ProcessLimits limits;
  long long memory_mib = 2048;
  if (const char* text = std::getenv("WOBBLE_STEP_SERVER_MEMORY_MIB"))
    memory_mib = std::atoll(text);
  limits.memory_bytes = memory_mib > 0 ? memory_mib << 20 : 0;
  limits.file_bytes = 64LL << 20;
  return limits;
}

// "5" or "0.5": a time limit as a person writes it.
std::string number_words(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

bool indices_below(const Eigen::MatrixXi& indices, Eigen::Index count) {
  return indices.size() == 0 || (indices.minCoeff() >= 0 && indices.maxCoeff() < count);
}

}  // namespace

StudentStep::StudentStep(const std::string& server_path, const Eigen::MatrixXd& V,
                         const Eigen::MatrixXi& E, double k, const Eigen::VectorXd& m,
                         const Eigen::VectorXi& b, double delta_t, double seconds_per_step)
    : vertex_count_(V.rows()), seconds_per_step_(seconds_per_step) {
  if (V.cols() != 3 || V.rows() == 0 || E.cols() != 2 || m.size() != V.rows() ||
      !indices_below(E, V.rows()) || !indices_below(b, V.rows()) ||
      V.rows() > step_protocol::kMaxCount || E.rows() > step_protocol::kMaxCount) {
    error_ =
        "bad problem for the student's step: expected V #V by 3, E #E by 2 and b indices "
        "into rows of V, m of #V masses";
    return;
  }

  int sockets[2], stderr_ends[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sockets) != 0) {
    error_ = std::string("cannot start the student's step server: ") + std::strerror(errno);
    return;
  }
  if (pipe2(stderr_ends, O_CLOEXEC) != 0) {
    error_ = std::string("cannot start the student's step server: ") + std::strerror(errno);
    close(sockets[0]);
    close(sockets[1]);
    return;
  }
  // In a process group of its own, so that whatever the student's code starts (a fork) ends
  // with it, here or when the viewer is stopped by a signal. Between fork and exec the child
  // makes only async-signal-safe calls (the viewer has threads and a GL context), and it gets
  // default signal handling and no blocked signals, whatever the viewer set for itself.
  server_ = spawn_bounded({server_path}, server_limits(),
                          ChildStreams{sockets[1], sockets[1], stderr_ends[1]});
  const int spawn_error = errno;
  close(sockets[1]);
  close(stderr_ends[1]);
  socket_ = sockets[0];
  stderr_pipe_ = stderr_ends[0];
  if (server_ < 0) {
    server_ = -1;
    fail("cannot start the student's step server " + server_path + ": " +
         std::strerror(spawn_error));
    return;
  }
  server_group_ = server_;
  end_on_termination_ = std::make_unique<EndGroupOnTermination>(server_group_, 0.0);
  fcntl(socket_, F_SETFL, fcntl(socket_, F_GETFL) | O_NONBLOCK);
  fcntl(stderr_pipe_, F_SETFL, fcntl(stderr_pipe_, F_GETFL) | O_NONBLOCK);

  const std::vector<char> message = encode_problem(V, E, k, m, b, delta_t);
  const double deadline = now_seconds() + seconds_per_step_;
  step_protocol::Header reply{};
  if (!send(message.data(), message.size(), deadline) || !receive(&reply, sizeof reply, deadline))
    return;
  if (std::memcmp(reply.magic, step_protocol::kReady, 4) != 0)
    fail("the student's step server answered something else than the protocol's reply");
  else if (reply.a == step_protocol::kNotFactored)
    fail("the reference precomputation failed: Q is not positive definite (are all masses > 0?)");
  else if (reply.a != step_protocol::kOk)
    fail("the student's step server refused the problem (status " + std::to_string(reply.a) + ")");
}

StudentStep::~StudentStep() {
  stop_server();
}

bool StudentStep::step(const Eigen::MatrixXd& fext, const Eigen::MatrixXd& Uprev,
                       const Eigen::MatrixXd& Ucur, Eigen::MatrixXd& Unext, std::string& error) {
  if (!running()) {
    error = error_;
    return false;
  }
  for (const Eigen::MatrixXd* input : {&fext, &Uprev, &Ucur}) {
    if (input->rows() != vertex_count_ || input->cols() != 3) {
      error = "fext, Uprev and Ucur must be #V by 3 (" + std::to_string(vertex_count_) +
              " by 3); one is " + std::to_string(input->rows()) + " by " +
              std::to_string(input->cols());
      return false;
    }
  }
  ++steps_done_;
  const std::vector<char> message = encode_step(fext, Uprev, Ucur);

  const double deadline = now_seconds() + seconds_per_step_;
  step_protocol::Header reply{};
  if (!send(message.data(), message.size(), deadline) || !receive(&reply, sizeof reply, deadline)) {
    error = error_;
    return false;
  }
  const std::string in_step = " in step " + std::to_string(steps_done_);
  if (std::memcmp(reply.magic, step_protocol::kNext, 4) != 0) {
    fail("the student's step server answered something else than the protocol's reply" + in_step);
  } else if (reply.a == step_protocol::kWrongShape) {
    fail("the student's fast_mass_springs_step_sparse returned Unext of " +
         std::to_string(reply.b) + " by " + std::to_string(reply.c) + ", expected " +
         std::to_string(vertex_count_) + " by 3" + in_step);
  } else if (reply.a == step_protocol::kThrew && reply.b >= 0 && reply.b <= 4096) {
    std::string text(static_cast<size_t>(reply.b), '\0');
    if (receive(text.data(), text.size(), deadline))
      fail("the student's fast_mass_springs_step_sparse " + text + in_step);
  } else if (reply.a != step_protocol::kOk || reply.b != vertex_count_ || reply.c != 3) {
    fail("the student's step server sent a malformed reply" + in_step);
  } else {
    RowMatrix rows(vertex_count_, 3);
    if (receive(rows.data(), sizeof(double) * rows.size(), deadline)) {
      Unext = rows;
      return true;
    }
  }
  error = error_;
  return false;
}

// Sends or receives all of `bytes`, draining the server's stderr meanwhile (a server blocked
// on a full stderr pipe would otherwise look like a hang). On a time-out, or the server
// closing its end, records why (transfer_failed) and returns false.
bool StudentStep::send(const void* data, size_t bytes, double deadline) {
  const char* from = static_cast<const char*>(data);
  while (bytes > 0) {
    const double left = deadline - now_seconds();
    if (left <= 0) return transfer_failed(true);
    pollfd waits[2] = {{socket_, POLLOUT, 0}, {stderr_pipe_, POLLIN, 0}};
    poll(waits, stderr_pipe_ >= 0 ? 2 : 1, static_cast<int>(left * 1000) + 1);
    if (waits[1].revents) drain_stderr();
    if (waits[0].revents & (POLLOUT | POLLERR | POLLHUP)) {
      const ssize_t n = ::send(socket_, from, bytes, MSG_NOSIGNAL | MSG_DONTWAIT);
      if (n > 0) {
        from += n;
        bytes -= static_cast<size_t>(n);
      } else if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
        return transfer_failed(false);
      }
    }
  }
  return true;
}

bool StudentStep::receive(void* data, size_t bytes, double deadline) {
  char* to = static_cast<char*>(data);
  while (bytes > 0) {
    const double left = deadline - now_seconds();
    if (left <= 0) return transfer_failed(true);
    pollfd waits[2] = {{socket_, POLLIN, 0}, {stderr_pipe_, POLLIN, 0}};
    poll(waits, stderr_pipe_ >= 0 ? 2 : 1, static_cast<int>(left * 1000) + 1);
    if (waits[1].revents) drain_stderr();
    if (waits[0].revents & (POLLIN | POLLERR | POLLHUP)) {
      const ssize_t n = recv(socket_, to, bytes, MSG_DONTWAIT);
      if (n > 0) {
        to += n;
        bytes -= static_cast<size_t>(n);
      } else if (n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
        return transfer_failed(false);
      }
    }
  }
  return true;
}

void StudentStep::drain_stderr() {
  if (stderr_pipe_ < 0) return;
  char buffer[4096];
  ssize_t n;
  while ((n = read(stderr_pipe_, buffer, sizeof buffer)) > 0) {
    stderr_tail_.append(buffer, static_cast<size_t>(n));
    if (stderr_tail_.size() > 8192) stderr_tail_.erase(0, stderr_tail_.size() - 8192);
  }
  if (n == 0) {  // the server closed its stderr (it ended): stop polling it
    close(stderr_pipe_);
    stderr_pipe_ = -1;
  }
}

bool StudentStep::transfer_failed(bool timed_out) {
  const std::string during =
      steps_done_ == 0 ? "the precomputation" : "step " + std::to_string(steps_done_);
  std::string message;
  int status = 0;
  pid_t ended = 0;
  if (!timed_out) {
    // The server closed the connection, so it is ending: give it a second to be reaped.
    for (int tries = 0; tries < 100 && (ended = waitpid(server_, &status, WNOHANG)) == 0; ++tries)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  drain_stderr();
  if (timed_out) {
    message = "the student's fast_mass_springs_step_sparse did not finish " + during + " within " +
              number_words(seconds_per_step_) + " s";
  } else if (ended == server_ && WIFSIGNALED(status)) {
    message = "the student's fast_mass_springs_step_sparse crashed with " +
              signal_words(WTERMSIG(status)) + " in " + during;
  } else if (ended == server_) {
    message = "the student's step server ended (exit code " + std::to_string(WEXITSTATUS(status)) +
              ") in " + during;
  } else {
    message = "the student's step server closed its connection in " + during;
  }
  if (ended == server_) server_ = -1;  // reaped already
  const std::string line = last_output_line(stderr_tail_);
  if (!line.empty()) message += " (its last output: \"" + line + "\")";
  fail(message);
  return false;
}

void StudentStep::fail(const std::string& what) {
  if (error_.empty()) error_ = what;
  stop_server();
}

void StudentStep::stop_server() {
  if (socket_ >= 0) close(socket_);  // the server reads end-of-file and exits
  socket_ = -1;
  if (server_ > 0) {
    int status = 0;
    pid_t ended = 0;
    for (int tries = 0; tries < 20 && (ended = waitpid(server_, &status, WNOHANG)) == 0; ++tries)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    if (ended == 0) {
      kill_group(server_group_, true);
      waitpid(server_, &status, 0);
    }
    server_ = -1;
  }
  // What the student's code started and left in the group (a fork) ends with the server.
  if (server_group_ > 0) kill_group(server_group_, false);
  server_group_ = -1;
  end_on_termination_.reset();
  if (stderr_pipe_ >= 0) close(stderr_pipe_);
  stderr_pipe_ = -1;
}

}  // namespace wobble

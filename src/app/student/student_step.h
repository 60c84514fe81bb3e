#ifndef WOBBLE_APP_STUDENT_STUDENT_STEP_H
#define WOBBLE_APP_STUDENT_STUDENT_STEP_H

#include <sys/types.h>

#include <Eigen/Core>
#include <memory>
#include <string>

#include "check/sandbox/bounded_process.h"

namespace wobble {

// A student's fast_mass_springs_step_sparse, run in a child process so that the viewer can show
// it beside Wobble's own step without the student's crash, endless loop or huge allocation
// taking the viewer down. The child is the step server that
//
//   scripts/check-assignment.sh --build-step-server DIR
//
// builds from DIR/fast_mass_springs_step_sparse.cpp; it runs Wobble's reference precomputation
// once, then the student's step for each request (src/check/step_server/step_protocol.h has the
// messages).
//
// The server runs in a process group of its own (check/bounded_process.h) within 2 GiB of
// address space (WOBBLE_STEP_SERVER_MEMORY_MIB) and 64 MiB a file, and stopping it ends its
// whole group, so a fork in the student's code leaves nothing behind; so does a SIGTERM,
// SIGINT or SIGHUP to the viewer.
//
// Nothing here throws or prints: a failure (the server cannot start, crashes, takes longer than
// the time limit, returns a wrong shape, throws) becomes an error string, and the server is
// stopped. Every later step() returns the same error; make a new StudentStep to try again.
// SIGPIPE cannot reach the viewer: writes use send(MSG_NOSIGNAL) on a socket.
class StudentStep {
 public:
  // Starts the server and sends it the problem.
  //   server_path       the step server's executable
  //   V                 #V by 3 rest positions (also the pin targets), m
  //   E                 #E by 2 spring indices into rows of V
  //   k                 stiffness, N/m
  //   m                 #V masses, kg
  //   b                 #b pinned vertex indices into rows of V
  //   delta_t           time step, s
  //   seconds_per_step  how long the precomputation, and then each step, may take
  StudentStep(const std::string& server_path, const Eigen::MatrixXd& V, const Eigen::MatrixXi& E,
              double k, const Eigen::VectorXd& m, const Eigen::VectorXi& b, double delta_t,
              double seconds_per_step = 5.0);
  ~StudentStep();
  StudentStep(const StudentStep&) = delete;
  StudentStep& operator=(const StudentStep&) = delete;

  // One step of the student's function.
  //   fext   #V by 3 external forces, N
  //   Uprev  #V by 3 positions at the previous time step, m
  //   Ucur   #V by 3 positions at the current time step (the initial guess), m
  //   Unext  #V by 3 positions at the next time step, m (written only on success)
  // Returns true on success; else false with `error` set, e.g. "the student's
  // fast_mass_springs_step_sparse crashed with SIGSEGV in step 3".
  bool step(const Eigen::MatrixXd& fext, const Eigen::MatrixXd& Uprev, const Eigen::MatrixXd& Ucur,
            Eigen::MatrixXd& Unext, std::string& error);

  // False once something failed; error() then says what.
  bool running() const { return error_.empty(); }
  const std::string& error() const { return error_; }

 private:
  bool send(const void* data, size_t bytes, double deadline);
  bool receive(void* data, size_t bytes, double deadline);
  void drain_stderr();
  bool transfer_failed(bool timed_out);  // says why a send or receive did not complete
  void fail(const std::string& what);    // records the first error and stops the server
  void stop_server();

  pid_t server_ = -1;        // not yet reaped
  pid_t server_group_ = -1;  // the server's process group, until it is ended
  std::unique_ptr<EndGroupOnTermination> end_on_termination_;
  int socket_ = -1;       // the server's stdin and stdout
  int stderr_pipe_ = -1;  // the server's stderr: its last line is quoted on a crash
  std::string stderr_tail_;
  std::string error_;
  Eigen::Index vertex_count_ = 0;
  double seconds_per_step_ = 5.0;
  int steps_done_ = 0;
};

}  // namespace wobble

#endif

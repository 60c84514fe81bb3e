// The step server: a student's fast_mass_springs_step_sparse, called as the course calls it
// (course_call.h: Unext comes in equal to Ucur), with Wobble's reference for every other
// function (the precomputation included, so only the step is the student's), serving steps
// over stdin and stdout in the messages of step_protocol.h. Built by
// scripts/check-assignment.sh --build-step-server DIR; driven by wobble::StudentStep.
//
// The prefactorization holds the pins with the weight the student's step uses, found once on
// the checker's probe (pin_weight.h) when it is an acceptable one, so a step written with
// another large w holds its pins in the viewer as in the course's program.
//
// Whatever the student's step prints goes to stderr: stdout carries only the protocol. The
// server limits its own address space (2 GiB, or WOBBLE_STEP_SERVER_MEMORY_MIB), so a dense
// matrix of a large mesh fails as an allocation error instead of swapping the machine.
#include <sys/resource.h>
#include <unistd.h>

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>

#include "course_call.h"
#include "fast_mass_springs_precomputation_sparse.h"
#include "pin_weight.h"
#include "step_protocol.h"

namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using RowIndices = Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

int protocol_out = -1;

bool read_all(void* data, size_t bytes) {
  char* to = static_cast<char*>(data);
  while (bytes > 0) {
    const ssize_t n = read(STDIN_FILENO, to, bytes);
    if (n <= 0) {
      if (n < 0 && errno == EINTR) continue;
      return false;
    }
    to += n;
    bytes -= static_cast<size_t>(n);
  }
  return true;
}

bool write_all(const void* data, size_t bytes) {
  const char* from = static_cast<const char*>(data);
  while (bytes > 0) {
    const ssize_t n = write(protocol_out, from, bytes);
    if (n <= 0) {
      if (n < 0 && errno == EINTR) continue;
      return false;
    }
    from += n;
    bytes -= static_cast<size_t>(n);
  }
  return true;
}

bool reply(const char (&magic)[4], std::int32_t status, std::int32_t rows, std::int32_t cols) {
  step_protocol::Header header{};
  std::memcpy(header.magic, magic, 4);
  header.a = status;
  header.b = rows;
  header.c = cols;
  return write_all(&header, sizeof header);
}

bool read_rows(RowMatrix& matrix, Eigen::Index rows, Eigen::Index cols) {
  matrix.resize(rows, cols);
  return read_all(matrix.data(), sizeof(double) * matrix.size());
}

// The pin weight the student's step uses, on the checker's probe: a vertex in no spring pinned
// away from the origin, at rest with no force; the handout's weight when it is not acceptable.
double student_pin_weight() {
  Eigen::MatrixXd V(3, 3);
  V << 0.25, 1.5, -0.5, 0.75, 2.0, -0.5, 1.25, 1.5, -0.5;
  Eigen::MatrixXi E(1, 2);
  E << 0, 1;
  const Eigen::Vector3d m(1.0, 0.5, 2.0);
  const Eigen::VectorXi b = Eigen::VectorXi::Constant(1, 2);
  const double k = 80, delta_t = 0.01;
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> M, A, C;
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> factor;
  if (!fast_mass_springs_precomputation_sparse(V, E, k, m, b, delta_t, r, M, A, C, factor))
    return kHandoutPinWeight;
  Eigen::MatrixXd Unext = V;
  try {
    course_call_fast_mass_springs_step_sparse(V, E, k, b, delta_t, Eigen::MatrixXd::Zero(3, 3), r,
                                              M, A, C, factor, V, V, Unext);
  } catch (const std::exception&) {
    return kHandoutPinWeight;  // the first real step says what is wrong
  }
  if (Unext.rows() != 3 || Unext.cols() != 3) return kHandoutPinWeight;
  const double w = step_pin_weight(V.row(2), Unext.row(2), m(2), delta_t, kHandoutPinWeight);
  return acceptable_pin_weight(w) ? w : kHandoutPinWeight;
}

bool valid_indices(const RowIndices& indices, int vertex_count) {
  return indices.size() == 0 || (indices.minCoeff() >= 0 && indices.maxCoeff() < vertex_count);
}

}  // namespace

int main() {
  // The protocol keeps the real stdout; anything printed to fd 1 from now on lands on stderr.
  protocol_out = dup(STDOUT_FILENO);
  dup2(STDERR_FILENO, STDOUT_FILENO);
  long long memory_mib = 2048;
  if (const char* text = std::getenv("WOBBLE_STEP_SERVER_MEMORY_MIB"))
    memory_mib = std::atoll(text);
  const rlimit memory{static_cast<rlim_t>(memory_mib) << 20, static_cast<rlim_t>(memory_mib) << 20};
  setrlimit(RLIMIT_AS, &memory);

  step_protocol::Header header{};
  if (!read_all(&header, sizeof header) ||
      std::memcmp(header.magic, step_protocol::kProblem, 4) != 0)
    return 1;
  const int n = header.a, springs = header.b, pins = header.c;
  const auto in_range = [](int count) { return count >= 0 && count <= step_protocol::kMaxCount; };
  if (!in_range(n) || !in_range(springs) || !in_range(pins) || n == 0) {
    reply(step_protocol::kReady, step_protocol::kBadMessage, 0, 0);
    return 1;
  }
  double k = 0, delta_t = 0;
  RowMatrix V_rows, m_rows;
  RowIndices E_rows(springs, 2), b_rows(pins, 1);
  if (!read_all(&k, sizeof k) || !read_all(&delta_t, sizeof delta_t) || !read_rows(V_rows, n, 3) ||
      !read_all(E_rows.data(), sizeof(int) * E_rows.size()) || !read_rows(m_rows, n, 1) ||
      !read_all(b_rows.data(), sizeof(int) * b_rows.size()))
    return 1;
  if (!valid_indices(E_rows, n) || !valid_indices(b_rows, n)) {
    reply(step_protocol::kReady, step_protocol::kBadMessage, 0, 0);
    return 1;
  }
  const Eigen::MatrixXd V = V_rows;
  const Eigen::MatrixXi E = E_rows;
  const Eigen::VectorXd m = Eigen::Map<Eigen::VectorXd>(m_rows.data(), n);
  const Eigen::VectorXi b = Eigen::Map<Eigen::VectorXi>(b_rows.data(), pins);

  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> M, A, C;
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> factor;
  if (!fast_mass_springs_precomputation_sparse(V, E, k, m, b, delta_t, r, M, A, C, factor)) {
    reply(step_protocol::kReady, step_protocol::kNotFactored, 0, 0);
    return 1;
  }
  if (!reply(step_protocol::kReady, step_protocol::kOk, 0, 0)) return 1;

  RowMatrix fext_rows, Uprev_rows, Ucur_rows;
  bool weighed = false;
  while (read_all(&header, sizeof header) &&
         std::memcmp(header.magic, step_protocol::kStep, 4) == 0) {
    if (header.a != n) {
      reply(step_protocol::kNext, step_protocol::kBadMessage, 0, 0);
      return 1;
    }
    if (!read_rows(fext_rows, n, 3) || !read_rows(Uprev_rows, n, 3) || !read_rows(Ucur_rows, n, 3))
      return 1;
    // Before the first step: the reference's precomputation holds the pins with the handout's
    // weight; refactor with the student's step's when that is another. Done here rather than
    // in the precomputation, so a step that crashes or hangs does so in step 1, as the viewer
    // says.
    if (!weighed) {
      weighed = true;
      const double weight = student_pin_weight();
      if (weight != kHandoutPinWeight) {
        // Q0 + w CᵀC is positive definite for any acceptable w, as the handout's Q is.
        const Eigen::SparseMatrix<double> CtC = C.transpose() * C;
        factor.compute(quadratic_without_pins(k, delta_t, M, A) + weight * CtC);
      }
    }
    const Eigen::MatrixXd Ucur = Ucur_rows;
    Eigen::MatrixXd Unext = Ucur;
    std::string error;
    try {
      course_call_fast_mass_springs_step_sparse(V, E, k, b, delta_t, fext_rows, r, M, A, C, factor,
                                                Uprev_rows, Ucur, Unext);
    } catch (const std::bad_alloc&) {
      error = "ran out of memory (more than " + std::to_string(memory_mib) + " MiB)";
    } catch (const std::exception& exception) {
      error = std::string("threw an exception: ") + exception.what();
    }
    if (!error.empty()) {
      if (!reply(step_protocol::kNext, step_protocol::kThrew, static_cast<int>(error.size()), 0) ||
          !write_all(error.data(), error.size()))
        return 1;
      continue;
    }
    const auto rows = static_cast<std::int32_t>(Unext.rows());
    const auto cols = static_cast<std::int32_t>(Unext.cols());
    if (rows != n || cols != 3) {
      if (!reply(step_protocol::kNext, step_protocol::kWrongShape, rows, cols)) return 1;
      continue;
    }
    const RowMatrix Unext_rows = Unext;
    if (!reply(step_protocol::kNext, step_protocol::kOk, rows, cols) ||
        !write_all(Unext_rows.data(), sizeof(double) * Unext_rows.size()))
      return 1;
  }
  return 0;
}

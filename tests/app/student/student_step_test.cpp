// wobble::StudentStep driving step servers that scripts/check-assignment.sh built from the seed
// and from planted copies of it (the CheckAssignment.BuildStepServers fixture, see
// tests/check/check_assignment_test.sh): the seed's server matches Wobble's own step, and a
// crashing, hanging, printing or missing server is an error string, never a crash or a hang of
// the process that drives it; what a forking one starts ends with it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "app/student/student_step.h"
#include "sim/seed/fast_mass_springs_precomputation_sparse.h"
#include "sim/seed/fast_mass_springs_step_sparse.h"

namespace {

std::string server(const std::string& name) {
  const std::string path = std::string(WOBBLE_STEP_SERVERS) + "/" + name;
  if (access(path.c_str(), X_OK) != 0)
    ADD_FAILURE() << path
                  << " is missing: ctest builds it first (CheckAssignment.BuildStepServers)";
  return path;
}

// A 6 by 5 cloth hanging from two corners, 0.1 m apart, with structural and shear springs.
struct Cloth {
  Eigen::MatrixXd V;
  Eigen::MatrixXi E;
  Eigen::VectorXd m;
  Eigen::VectorXi b;
  Eigen::MatrixXd fext;
  double k = 400.0, delta_t = 0.01;

  Cloth(int nx = 6, int ny = 5) {
    V.resize(nx * ny, 3);
    std::vector<Eigen::Vector2i> springs;
    for (int y = 0; y < ny; ++y) {
      for (int x = 0; x < nx; ++x) {
        const int i = y * nx + x;
        V.row(i) << 0.1 * x, 1.0 - 0.1 * y, 0.01 * ((x * 7 + y * 3) % 5);
        if (x + 1 < nx) springs.emplace_back(i, i + 1);
        if (y + 1 < ny) springs.emplace_back(i, i + nx);
        if (x + 1 < nx && y + 1 < ny) springs.emplace_back(i, i + nx + 1);
      }
    }
    E.resize(static_cast<int>(springs.size()), 2);
    for (int e = 0; e < E.rows(); ++e)
      E.row(e) = springs[e].transpose();
    m = Eigen::VectorXd::Constant(V.rows(), 0.05);
    b.resize(2);
    b << 0, nx - 1;
    fext = Eigen::MatrixXd::Zero(V.rows(), 3);
    fext.col(1) = -9.8 * m;
  }
};

// Runs `steps` steps through the server and through Wobble's own seed, returning the largest
// distance between them (m); -1 if the server failed.
double compare_with_seed(const std::string& server_path, int steps) {
  const Cloth cloth;
  wobble::StudentStep student(server_path, cloth.V, cloth.E, cloth.k, cloth.m, cloth.b,
                              cloth.delta_t);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> M, A, C;
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> factor;
  EXPECT_TRUE(fast_mass_springs_precomputation_sparse(cloth.V, cloth.E, cloth.k, cloth.m, cloth.b,
                                                      cloth.delta_t, r, M, A, C, factor));
  Eigen::MatrixXd Uprev = cloth.V, Ucur = cloth.V, expected, Unext;
  double worst = 0;
  for (int step = 0; step < steps; ++step) {
    fast_mass_springs_step_sparse(cloth.V, cloth.E, cloth.k, cloth.b, cloth.delta_t, cloth.fext, r,
                                  M, A, C, factor, Uprev, Ucur, expected);
    std::string error;
    if (!student.step(cloth.fext, Uprev, Ucur, Unext, error)) {
      ADD_FAILURE() << error;
      return -1;
    }
    worst = std::max(worst, (Unext - expected).rowwise().norm().maxCoeff());
    Uprev = Ucur;
    Ucur = expected;
  }
  EXPECT_TRUE(student.running());
  return worst;
}

TEST(StudentStep, SeedServerMatchesWobblesOwnStep) {
  // The same source compiled twice (the script's -O2 with Eigen's assertions, CMake's Release):
  // only the order of vectorized sums can differ, far below 1e-12 m on a 0.6 m cloth.
  const double worst = compare_with_seed(server("reference"), 20);
  EXPECT_GE(worst, 0.0);
  EXPECT_LE(worst, 1e-12);
}

TEST(StudentStep, StudentOutputDoesNotDisturbTheMessages) {
  // This server's step prints to stdout, the protocol's channel, every step.
  const double worst = compare_with_seed(server("printing"), 5);
  EXPECT_GE(worst, 0.0);
  EXPECT_LE(worst, 1e-12);
}

TEST(StudentStep, CrashIsAnErrorAndLaterStepsRepeatIt) {
  // This server's step crashes (null pointer write) once vertex 0 is below y = -0.05.
  const Cloth cloth;
  wobble::StudentStep student(server("crashing"), cloth.V, cloth.E, cloth.k, cloth.m, cloth.b,
                              cloth.delta_t);
  Eigen::MatrixXd Unext;
  std::string error;
  ASSERT_TRUE(student.step(cloth.fext, cloth.V, cloth.V, Unext, error)) << error;
  Eigen::MatrixXd low = cloth.V;
  low(0, 1) = -1.0;
  EXPECT_FALSE(student.step(cloth.fext, cloth.V, low, Unext, error));
  EXPECT_EQ(error, "the student's fast_mass_springs_step_sparse crashed with SIGSEGV in step 2");
  EXPECT_FALSE(student.running());
  std::string again;
  EXPECT_FALSE(student.step(cloth.fext, cloth.V, cloth.V, Unext, again));
  EXPECT_EQ(again, error);
}

TEST(StudentStep, HangIsATimeOut) {
  const Cloth cloth;
  wobble::StudentStep student(server("hanging"), cloth.V, cloth.E, cloth.k, cloth.m, cloth.b,
                              cloth.delta_t, 0.5);
  Eigen::MatrixXd Unext;
  std::string error;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(student.step(cloth.fext, cloth.V, cloth.V, Unext, error));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(error,
            "the student's fast_mass_springs_step_sparse did not finish step 1 within 0.5 s");
  EXPECT_LT(seconds, 3.0);  // 0.5 s and the kill, with room for a busy machine
}

TEST(StudentStep, ServerThatEndsAtOnceDoesNotKillTheCallerWithSigpipe) {
  // /bin/true reads nothing and exits: the problem (17 MB, far more than a socket holds) is written
  // into a closed connection. Without MSG_NOSIGNAL this process would die of SIGPIPE.
  const Cloth cloth(300, 1000);
  wobble::StudentStep student("/bin/true", cloth.V, cloth.E, cloth.k, cloth.m, cloth.b,
                              cloth.delta_t);
  EXPECT_FALSE(student.running());
  EXPECT_EQ(student.error(), "the student's step server ended (exit code 0) in the precomputation");
}

TEST(StudentStep, MissingServerIsAnError) {
  const Cloth cloth;
  wobble::StudentStep student("/nonexistent/step-server", cloth.V, cloth.E, cloth.k, cloth.m,
                              cloth.b, cloth.delta_t);
  EXPECT_FALSE(student.running());
  EXPECT_NE(student.error().find("cannot start the student's step server /nonexistent/step-server"),
            std::string::npos)
      << student.error();
  Eigen::MatrixXd Unext;
  std::string error;
  EXPECT_FALSE(student.step(cloth.fext, cloth.V, cloth.V, Unext, error));
  EXPECT_EQ(error, student.error());
}

// How many running processes carry `entry` (NAME=VALUE) in their environment, after up to
// `seconds` for that count to reach `wanted`.
int processes_with(const std::string& entry, int wanted, double seconds) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  for (;;) {
    int count = 0;
    for (const auto& process : std::filesystem::directory_iterator("/proc")) {
      const std::string name = process.path().filename().string();
      if (name.find_first_not_of("0123456789") != std::string::npos) continue;
      std::ifstream environ(process.path() / "environ", std::ios::binary);
      for (std::string variable; std::getline(environ, variable, '\0');)
        count += variable == entry;
    }
    if (count == wanted || std::chrono::steady_clock::now() > until) return count;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

TEST(StudentStep, AForkInTheStepLeavesNothingBehindOnceStopped) {
  // This server forks a child that sleeps 300 s in a static initializer, and another in every
  // step. The server and its children carry a marker in their environment.
  const std::string value = std::to_string(getpid()) + "-forking";
  setenv("WOBBLE_STUDENT_STEP_TEST", value.c_str(), 1);
  const std::string entry = "WOBBLE_STUDENT_STEP_TEST=" + value;
  {
    const Cloth cloth;
    wobble::StudentStep student(server("forking"), cloth.V, cloth.E, cloth.k, cloth.m, cloth.b,
                                cloth.delta_t);
    unsetenv("WOBBLE_STUDENT_STEP_TEST");
    Eigen::MatrixXd Unext;
    std::string error;
    for (int step = 0; step < 3; ++step)
      ASSERT_TRUE(student.step(cloth.fext, cloth.V, cloth.V, Unext, error)) << error;
    // The server, the static initializer's child and a child for every step (the server's
    // probe of the pin weight is one more).
    EXPECT_GE(processes_with(entry, -1, 0.0), 5);
  }
  EXPECT_EQ(processes_with(entry, 0, 2.0), 0)
      << "the student's forked children outlived the server";
}

TEST(StudentStep, WrongInputShapeIsRefusedWithoutStoppingTheServer) {
  const Cloth cloth;
  wobble::StudentStep student(server("reference"), cloth.V, cloth.E, cloth.k, cloth.m, cloth.b,
                              cloth.delta_t);
  Eigen::MatrixXd Unext;
  std::string error;
  EXPECT_FALSE(student.step(cloth.fext.topRows(3), cloth.V, cloth.V, Unext, error));
  EXPECT_NE(error.find("must be #V by 3 (30 by 3); one is 3 by 3"), std::string::npos) << error;
  EXPECT_TRUE(student.running());
  EXPECT_TRUE(student.step(cloth.fext, cloth.V, cloth.V, Unext, error)) << error;
  EXPECT_EQ(Unext.rows(), 30);
}

}  // namespace

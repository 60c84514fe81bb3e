#include "solve_cost.h"

#include <Eigen/SparseCholesky>
#include <chrono>
#include <cstdio>
#include <vector>

#include "benchmark_scenes.h"
#include "median.h"
#include "sim/seed/fast_mass_springs_precomputation_sparse.h"
#include "sim/solver/cholesky_solver.h"

namespace wobble::benchmark {

namespace {

using Clock = std::chrono::steady_clock;

double milliseconds_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

Eigen::SparseMatrix<double> system_matrix(const Scene& scene) {
  const SpringNetwork& network = scene.network;
  Eigen::VectorXi b(scene.pins.size());
  for (std::size_t i = 0; i < scene.pins.size(); ++i)
    b(i) = scene.pins[i];
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> M, A, C;
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> unused;
  fast_mass_springs_precomputation_sparse(network.V, network.E, scene.params.k, network.m, b,
                                          scene.params.dt, r, M, A, C, unused);
  const double dt = scene.params.dt;
  Eigen::SparseMatrix<double> Q = scene.params.k * A.transpose() * A;
  Q += M / (dt * dt);
  Q += 1e10 * C.transpose() * C;
  return Q;
}

}  // namespace

void print_solve_cost() {
  std::printf(
      "\nThe solver alone (median ms of runs in turn; Eigen: SimplicialLLT on the #V by 3 "
      "right-hand side):\n\n"
      "| scene | nnz(L) | solve: Eigen / Wobble | speed-up | factorize: Eigen / Wobble 1 thread "
      "/ Wobble %d threads | speed-up |\n|---|---|---|---|---|---|\n",
      WorkerPool::shared().threads());
  for (const BenchmarkScene& entry : benchmark_scenes()) {
    const Eigen::SparseMatrix<double> Q = system_matrix(entry.scene);
    const Eigen::MatrixXd b = Eigen::MatrixXd::Random(Q.rows(), 3);
    Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> eigen;
    eigen.analyzePattern(Q);
    WorkerPool one_thread(1);
    CholeskySolver alone, shared;
    alone.set_pool(one_thread);
    alone.analyze(Q);
    shared.analyze(Q);
    const int runs = Q.rows() > 30'000 ? 7 : 21;
    std::vector<double> eigen_factor, alone_factor, shared_factor, eigen_solve, wobble_solve;
    Eigen::MatrixXd x_eigen, x_wobble;
    for (int run = 0; run < runs; ++run) {
      Clock::time_point start = Clock::now();
      eigen.factorize(Q);
      eigen_factor.push_back(milliseconds_since(start));
      start = Clock::now();
      alone.factorize(Q);
      alone_factor.push_back(milliseconds_since(start));
      start = Clock::now();
      shared.factorize(Q);
      shared_factor.push_back(milliseconds_since(start));
      for (int solve = 0; solve < 3; ++solve) {
        start = Clock::now();
        x_eigen = eigen.solve(b);
        eigen_solve.push_back(milliseconds_since(start));
        start = Clock::now();
        shared.solve(b, x_wobble);
        wobble_solve.push_back(milliseconds_since(start));
      }
    }
    const double difference = (x_eigen - x_wobble).norm() / x_eigen.norm();
    std::printf("| %s | %ld | %.2f / %.2f | %.1f× | %.1f / %.1f / %.1f | %.1f× / %.1f× |%s\n",
                entry.name.c_str(), shared.factor_nonzeros(), median(eigen_solve),
                median(wobble_solve), median(eigen_solve) / median(wobble_solve),
                median(eigen_factor), median(alone_factor), median(shared_factor),
                median(eigen_factor) / median(alone_factor),
                median(eigen_factor) / median(shared_factor),
                difference < 1e-5 ? "" : " (solutions differ!)");
  }
}

}  // namespace wobble::benchmark

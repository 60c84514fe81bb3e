#include "sim/solver/cholesky_solver.h"

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <cstdio>

#include "sim/shapes/cloth_grid.h"

namespace {

// Q = k AᵀA + M/Δt² + w CᵀC for a small cloth, as the simulation builds it; with `extra`, a
// second cloth of that resolution and a vertex without springs follow, unconnected to it.
Eigen::SparseMatrix<double> cloth_system(double k, double pin_weight, int resolution = 9,
                                         int extra = 0) {
  wobble::ClothGridOptions options;
  options.resolution = resolution;
  wobble::SpringNetwork cloth = wobble::make_cloth_grid(options);
  if (extra > 0) {
    options.resolution = extra;
    const wobble::SpringNetwork second = wobble::make_cloth_grid(options);
    const Eigen::Index n = cloth.V.rows(), m = second.V.rows(), e = cloth.E.rows();
    cloth.m.conservativeResize(n + m + 1);
    cloth.m.segment(n, m) = second.m;
    cloth.m(n + m) = cloth.m(0);
    cloth.V.conservativeResize(n + m + 1, 3);
    cloth.E.conservativeResize(e + second.E.rows(), 2);
    cloth.E.bottomRows(second.E.rows()) = second.E.array() + static_cast<int>(n);
  }
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index i = 0; i < cloth.V.rows(); ++i)
    entries.emplace_back(i, i, cloth.m(i) * 3600.0);
  for (Eigen::Index e = 0; e < cloth.E.rows(); ++e) {
    const int i = cloth.E(e, 0), j = cloth.E(e, 1);
    entries.emplace_back(i, i, k);
    entries.emplace_back(j, j, k);
    entries.emplace_back(i, j, -k);
    entries.emplace_back(j, i, -k);
  }
  entries.emplace_back(0, 0, pin_weight);
  Eigen::SparseMatrix<double> Q(cloth.V.rows(), cloth.V.rows());
  Q.setFromTriplets(entries.begin(), entries.end());
  return Q;
}

// Wobble's solve of Q x = b, for a #V by 3 b, against Eigen's SimplicialLLT, which uses the
// same AMD ordering: exactly the nonzeros of Eigen's L, no more, and the same x up to rounding
// (the same factor, applied in another order).
void expect_like_eigen(const Eigen::SparseMatrix<double>& Q, double tolerance) {
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(Q.rows(), 3);
  wobble::CholeskySolver solver;
  solver.analyze(Q);
  ASSERT_TRUE(solver.factorize(Q));
  Eigen::MatrixXd x;
  solver.solve(b, x);
  const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> eigen(Q);
  const Eigen::SparseMatrix<double> L = eigen.matrixL();
  EXPECT_EQ(solver.factor_nonzeros(), L.nonZeros());
  const Eigen::MatrixXd expected = eigen.solve(b);
  EXPECT_LE((x - expected).norm(), tolerance * expected.norm());
  EXPECT_LE((Q * x - b).norm(), 1e-6 * b.norm());  // w = 1e10 makes Q ill-conditioned
}

TEST(CholeskySolver, SolvesAllThreeCoordinatesLikeEigen) {
  expect_like_eigen(cloth_system(400.0, 1e10), 1e-12);
}

TEST(CholeskySolver, FindsEigensFactorPatternAndSolvesLikeItOnAForest) {
  // A 40×40 cloth has supernodes wide enough for every path of the block solve; with a second
  // cloth and a lone vertex the elimination tree is a forest.
  expect_like_eigen(cloth_system(400.0, 1e10, 40, 12), 1e-11);
}

TEST(CholeskySolver, ALargeFactorIsReadInSinglePrecisionToAboutFloatAccuracy) {
  const Eigen::SparseMatrix<double> Q = cloth_system(400.0, 1e10);
  Eigen::MatrixXd b = Eigen::MatrixXd::Random(Q.rows(), 3);
  b.row(0) *= 1e10;  // a pin's target, as the simulation weights it
  wobble::CholeskySolver exact, single;
  exact.analyze(Q);
  ASSERT_TRUE(exact.factorize(Q));
  EXPECT_FALSE(exact.solves_in_single_precision()) << "a small factor stays double";
  single.set_single_precision_above(0);
  single.analyze(Q);
  ASSERT_TRUE(single.factorize(Q));
  ASSERT_TRUE(single.solves_in_single_precision());
  Eigen::MatrixXd x_exact, x_single;
  exact.solve(b, x_exact);
  single.solve(b, x_single);
  const double error = (x_single - x_exact).norm() / x_exact.norm();
  EXPECT_LT(error, 1e-6);
  EXPECT_GT(error, 1e-12) << "the values were not rounded";
  // The pinned row still sits on its target.
  EXPECT_NEAR(x_single(0, 0), x_exact(0, 0), 1e-6 * std::abs(x_exact(0, 0)));
}

TEST(CholeskySolver, TheSameBitsOnOneThreadOrSeveral) {
  // A factor large enough to be factorized in two parts side by side.
  const Eigen::SparseMatrix<double> Q = cloth_system(400.0, 1e10, 70);
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(Q.rows(), 3);
  wobble::WorkerPool one_thread(1), three_threads(3);
  wobble::CholeskySolver alone, shared;
  alone.set_pool(one_thread);
  shared.set_pool(three_threads);
  alone.analyze(Q);
  shared.analyze(Q);
  ASSERT_GT(shared.factor_nonzeros(), wobble::CholeskySolver::parallel_factorization_above);
  ASSERT_TRUE(alone.factorize(Q));
  Eigen::MatrixXd expected, x;
  alone.solve(b, expected);
  for (int repeat = 0; repeat < 10; ++repeat) {
    ASSERT_TRUE(shared.factorize(Q));
    shared.solve(b, x);
    ASSERT_EQ(x, expected) << "repeat " << repeat;
  }
}

TEST(CholeskySolver, TheCurtainsFactorOnOneAndOnTwoThreadsSolvesLikeEigens) {
  // The curtain's system: 81 × 81 vertices, k = 2000, the top edge pinned.
  Eigen::SparseMatrix<double> Q = cloth_system(2000.0, 1e10, 81);
  for (int column = 1; column < 81; ++column)
    Q.coeffRef(column, column) += 1e10;
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(Q.rows(), 3);
  const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> eigen(Q);
  ASSERT_EQ(eigen.info(), Eigen::Success);
  const Eigen::SparseMatrix<double> L = eigen.matrixL();
  const Eigen::MatrixXd expected = eigen.solve(b);
  for (const int threads : {1, 2}) {
    wobble::WorkerPool pool(threads);
    wobble::CholeskySolver solver;
    solver.set_pool(pool);
    solver.analyze(Q);
    EXPECT_EQ(solver.factor_nonzeros(), 417'470);
    EXPECT_EQ(solver.factor_nonzeros(), L.nonZeros());
    ASSERT_GT(solver.factor_nonzeros(), wobble::CholeskySolver::parallel_factorization_above)
        << "the factorization in two parts";
    // Factorized several times: with two threads, the helper wakes in time for some of them.
    for (int repeat = 0; repeat < 5; ++repeat) {
      ASSERT_TRUE(solver.factorize(Q));
      Eigen::MatrixXd x;
      solver.solve(b, x);
      EXPECT_LE((x - expected).norm(), 1e-10 * expected.norm())
          << threads << " threads, repeat " << repeat;
      EXPECT_LE((Q * x - b).norm(), 1e-6 * b.norm());
    }
    if (threads == 1) {
      EXPECT_EQ(pool.helper_tasks(), 0);
    }
    std::printf("%d threads: %ld of the parts ran on the helper\n", threads, pool.helper_tasks());
  }
}

TEST(CholeskySolver, RefactorizesNewValuesOnTheSamePattern) {
  wobble::CholeskySolver solver;
  const Eigen::SparseMatrix<double> soft = cloth_system(10.0, 1e10);
  const Eigen::SparseMatrix<double> stiff = cloth_system(5000.0, 1e10);
  solver.analyze(soft);
  ASSERT_TRUE(solver.factorize(soft));
  ASSERT_TRUE(solver.factorize(stiff));
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(stiff.rows(), 3);
  Eigen::MatrixXd x;
  solver.solve(b, x);
  EXPECT_LE((stiff * x - b).norm(), 1e-6 * b.norm());
}

TEST(CholeskySolver, RefusesAMatrixThatIsNotPositiveDefinite) {
  Eigen::SparseMatrix<double> Q = cloth_system(400.0, 1e10);
  wobble::CholeskySolver solver;
  solver.analyze(Q);
  Q.coeffRef(3, 3) = -1.0;
  EXPECT_FALSE(solver.factorize(Q));
}

}  // namespace

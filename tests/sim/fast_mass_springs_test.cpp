// The seed functions: the dense forms are the oracle for the sparse ones.
#include <gtest/gtest.h>

#include "sim/seed/fast_mass_springs_precomputation_dense.h"
#include "sim/seed/fast_mass_springs_precomputation_sparse.h"
#include "sim/seed/fast_mass_springs_step_dense.h"
#include "sim/seed/fast_mass_springs_step_sparse.h"
#include "test_meshes.h"

namespace {

using wobble::testing::all_test_meshes;
using wobble::testing::gravity_forces;
using wobble::testing::pin_vector;

constexpr double k = 200.0;
constexpr double dt = 1.0 / 60.0;

struct DenseSeed {
  Eigen::VectorXd r;
  Eigen::MatrixXd M, A, C;
  Eigen::LLT<Eigen::MatrixXd> llt;
};

struct SparseSeed {
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> M, A, C;
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> llt;
};

// Precompute both forms for one test mesh with the constants above; false if either fails.
bool precompute_both(const wobble::testing::TestMesh& mesh, DenseSeed& dense, SparseSeed& sparse) {
  const auto& net = mesh.network;
  const Eigen::VectorXi b = pin_vector(mesh.pins);
  return fast_mass_springs_precomputation_dense(net.V, net.E, k, net.m, b, dt, dense.r, dense.M,
                                                dense.A, dense.C, dense.llt) &&
         fast_mass_springs_precomputation_sparse(net.V, net.E, k, net.m, b, dt, sparse.r, sparse.M,
                                                 sparse.A, sparse.C, sparse.llt);
}

TEST(FastMassSpringsPrecomputation, SparseEqualsDense) {
  for (const auto& mesh : all_test_meshes()) {
    SCOPED_TRACE(mesh.name);
    const auto& net = mesh.network;
    const Eigen::VectorXi b = pin_vector(mesh.pins);
    DenseSeed dense;
    SparseSeed sparse;
    ASSERT_TRUE(precompute_both(mesh, dense, sparse));
    // Both build r, M, A and C from the same exact operations, so they agree to the bit; 1e-9
    // is the bound and leaves room for a different summation order.
    EXPECT_LE((sparse.r - dense.r).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_LE((Eigen::MatrixXd(sparse.M) - dense.M).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_LE((Eigen::MatrixXd(sparse.A) - dense.A).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_LE((Eigen::MatrixXd(sparse.C) - dense.C).cwiseAbs().maxCoeff(), 1e-9);
    // setFromTriplets with no explicit zeros: M is diagonal, A has 2 per row, C 1 per row.
    EXPECT_EQ(sparse.M.nonZeros(), net.V.rows());
    EXPECT_EQ(sparse.A.nonZeros(), 2 * net.E.rows());
    EXPECT_EQ(sparse.C.nonZeros(), b.size());
    EXPECT_EQ(dense.C.rows(), b.size());
    for (Eigen::Index c = 0; c < b.size(); ++c)
      EXPECT_EQ(dense.C(c, b(c)), 1.0);
  }
}

TEST(FastMassSpringsPrecomputation, RestLengthsAreEdgeLengths) {
  const auto mesh = wobble::testing::chain_mesh(3);
  DenseSeed dense;
  ASSERT_TRUE(fast_mass_springs_precomputation_dense(
      mesh.network.V, mesh.network.E, k, mesh.network.m, pin_vector(mesh.pins), dt, dense.r,
      dense.M, dense.A, dense.C, dense.llt));
  ASSERT_EQ(dense.r.size(), 3);
  for (int e = 0; e < 3; ++e)
    EXPECT_NEAR(dense.r(e), 0.1, 1e-15);
}

TEST(FastMassSpringsPrecomputation, ReportsAFailedFactorization) {
  // Negative masses with weak springs make Q indefinite, so Cholesky must fail.
  auto mesh = wobble::testing::chain_mesh(3);
  mesh.network.m.setConstant(-1.0);
  DenseSeed dense;
  SparseSeed sparse;
  EXPECT_FALSE(fast_mass_springs_precomputation_dense(
      mesh.network.V, mesh.network.E, 1.0, mesh.network.m, Eigen::VectorXi(), dt, dense.r, dense.M,
      dense.A, dense.C, dense.llt));
  EXPECT_FALSE(fast_mass_springs_precomputation_sparse(
      mesh.network.V, mesh.network.E, 1.0, mesh.network.m, Eigen::VectorXi(), dt, sparse.r,
      sparse.M, sparse.A, sparse.C, sparse.llt));
}

TEST(FastMassSpringsStep, SparseEqualsDenseFor100Steps) {
  for (const auto& mesh : all_test_meshes()) {
    SCOPED_TRACE(mesh.name);
    const auto& net = mesh.network;
    const Eigen::VectorXi b = pin_vector(mesh.pins);
    const Eigen::MatrixXd fext = gravity_forces(net.m);
    DenseSeed dense;
    SparseSeed sparse;
    ASSERT_TRUE(precompute_both(mesh, dense, sparse));
    Eigen::MatrixXd dense_prev = net.V, dense_cur = net.V, dense_next;
    Eigen::MatrixXd sparse_prev = net.V, sparse_cur = net.V, sparse_next;
    double largest_motion = 0.0;
    for (int step = 0; step < 100; ++step) {
      fast_mass_springs_step_dense(net.V, net.E, k, b, dt, fext, dense.r, dense.M, dense.A, dense.C,
                                   dense.llt, dense_prev, dense_cur, dense_next);
      fast_mass_springs_step_sparse(net.V, net.E, k, b, dt, fext, sparse.r, sparse.M, sparse.A,
                                    sparse.C, sparse.llt, sparse_prev, sparse_cur, sparse_next);
      // Both solve the same SPD system in double precision (different orderings), so they may
      // differ only by rounding: 1e-9 m on a shape about 0.1 to 1 m across.
      ASSERT_LE((dense_next - sparse_next).cwiseAbs().maxCoeff(), 1e-9) << "step " << step;
      largest_motion = std::max(largest_motion, (sparse_next - net.V).cwiseAbs().maxCoeff());
      dense_prev = dense_cur;
      dense_cur = dense_next;
      sparse_prev = sparse_cur;
      sparse_cur = sparse_next;
    }
    // Not vacuous: the shapes really moved under gravity.
    EXPECT_GT(largest_motion, 1e-3);
  }
}

TEST(FastMassSpringsStep, PinnedVerticesStayAtTheirRestPositions) {
  for (const auto& mesh : all_test_meshes()) {
    SCOPED_TRACE(mesh.name);
    const auto& net = mesh.network;
    const Eigen::VectorXi b = pin_vector(mesh.pins);
    SparseSeed sparse;
    ASSERT_TRUE(fast_mass_springs_precomputation_sparse(net.V, net.E, k, net.m, b, dt, sparse.r,
                                                        sparse.M, sparse.A, sparse.C, sparse.llt));
    Eigen::MatrixXd prev = net.V, cur = net.V, next;
    for (int step = 0; step < 100; ++step) {
      fast_mass_springs_step_sparse(net.V, net.E, k, b, dt, gravity_forces(net.m), sparse.r,
                                    sparse.M, sparse.A, sparse.C, sparse.llt, prev, cur, next);
      for (int pin : mesh.pins) {
        // w = 1e10 against forces of order 1 N leaves the pins ~1e-10 m off target.
        ASSERT_LE((next.row(pin) - net.V.row(pin)).norm(), 1e-6) << "pin " << pin;
      }
      prev = cur;
      cur = next;
    }
  }
}

TEST(FastMassSpringsStep, ZeroLengthSpringGivesNoNaN) {
  // Two vertices at the same rest position: r = 0 and the spring direction is undefined.
  Eigen::MatrixXd V(3, 3);
  V << 0, 0, 0, 0, 0, 0, 0.1, 0, 0;
  Eigen::MatrixXi E(2, 2);
  E << 0, 1, 1, 2;
  const Eigen::VectorXd m = Eigen::VectorXd::Constant(3, 0.1);
  const Eigen::VectorXi b = Eigen::VectorXi::Constant(1, 2);
  SparseSeed sparse;
  ASSERT_TRUE(fast_mass_springs_precomputation_sparse(V, E, k, m, b, dt, sparse.r, sparse.M,
                                                      sparse.A, sparse.C, sparse.llt));
  Eigen::MatrixXd next;
  fast_mass_springs_step_sparse(V, E, k, b, dt, gravity_forces(m), sparse.r, sparse.M, sparse.A,
                                sparse.C, sparse.llt, V, V, next);
  EXPECT_TRUE(next.allFinite());
  EXPECT_LT(next(0, 1), 0.0);  // gravity still acts
}

}  // namespace

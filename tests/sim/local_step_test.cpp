#include "sim/solver/local_step.h"

#include <gtest/gtest.h>

#include "sim/seed/signed_incidence_matrix_sparse.h"
#include "sim/shapes/cloth_grid.h"

namespace {

struct Fixture {
  Fixture() {
    wobble::ClothGridOptions options;
    options.resolution = 24;  // enough springs for apply() to use threads
    cloth = wobble::make_cloth_grid(options);
    r.resize(cloth.E.rows());
    for (Eigen::Index e = 0; e < cloth.E.rows(); ++e)
      r(e) = (cloth.V.row(cloth.E(e, 0)) - cloth.V.row(cloth.E(e, 1))).norm();
    p = cloth.V + 0.01 * Eigen::MatrixXd::Random(cloth.V.rows(), 3);
    y = Eigen::MatrixXd::Random(cloth.V.rows(), 3);
  }
  wobble::SpringNetwork cloth;
  Eigen::VectorXd r;
  Eigen::MatrixXd p, y;
};

TEST(LocalStep, MatchesKAtransposeDPlusY) {
  Fixture f;
  wobble::LocalStep local(f.cloth.E, f.r, f.cloth.V);
  Eigen::MatrixXd rhs(f.p.rows(), 3);
  local.apply(f.p, 250.0, f.y, rhs);
  // The assignment's form: d from the normalized spring vectors, then k Aᵀd + y.
  Eigen::SparseMatrix<double> A;
  signed_incidence_matrix_sparse(f.p.rows(), f.cloth.E, A);
  Eigen::MatrixXd d(f.cloth.E.rows(), 3);
  for (Eigen::Index e = 0; e < f.cloth.E.rows(); ++e)
    d.row(e) = f.r(e) * (f.p.row(f.cloth.E(e, 0)) - f.p.row(f.cloth.E(e, 1))).normalized();
  const Eigen::MatrixXd expected = 250.0 * (A.transpose() * d) + f.y;
  EXPECT_LE((rhs - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
}

TEST(LocalStep, CoincidentEndsPushApartAlongTheRestDirection) {
  Fixture f;
  const int i = f.cloth.E(0, 0), j = f.cloth.E(0, 1);
  f.p.row(j) = f.p.row(i);
  wobble::LocalStep local(f.cloth.E, f.r, f.cloth.V);
  Eigen::MatrixXd rhs(f.p.rows(), 3);
  local.apply(f.p, 1.0, Eigen::MatrixXd::Zero(f.p.rows(), 3), rhs);
  EXPECT_TRUE(rhs.allFinite());
}

TEST(LocalStep, SameResultOnOneThreadOrSeveral) {
  Fixture f;
  ASSERT_GE(f.cloth.E.rows(), wobble::LocalStep::min_springs_for_threads);
  wobble::WorkerPool one_thread(1), three_threads(3);
  wobble::LocalStep alone(f.cloth.E, f.r, f.cloth.V, one_thread);
  wobble::LocalStep shared(f.cloth.E, f.r, f.cloth.V, three_threads);
  Eigen::MatrixXd one(f.p.rows(), 3), three(f.p.rows(), 3);
  alone.apply(f.p, 400.0, f.y, one);
  for (int repeat = 0; repeat < 50; ++repeat) {
    three.setZero();
    shared.apply(f.p, 400.0, f.y, three);
    ASSERT_EQ(one, three) << "repeat " << repeat;  // bit for bit: fixed order per vertex
  }
}

}  // namespace

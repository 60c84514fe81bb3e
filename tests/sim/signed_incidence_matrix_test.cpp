#include <gtest/gtest.h>

#include "sim/seed/signed_incidence_matrix_dense.h"
#include "sim/seed/signed_incidence_matrix_sparse.h"
#include "test_meshes.h"

namespace {

TEST(SignedIncidenceMatrix, DenseMatchesTheAssignmentExample) {
  Eigen::MatrixXi E(3, 2);
  E << 0, 1, 1, 2, 2, 3;
  Eigen::MatrixXd A;
  signed_incidence_matrix_dense(4, E, A);
  Eigen::MatrixXd expected(3, 4);
  expected << 1, -1, 0, 0,  //
      0, 1, -1, 0,          //
      0, 0, 1, -1;
  EXPECT_EQ(A, expected);
}

TEST(SignedIncidenceMatrix, SparseMatchesTheAssignmentExample) {
  Eigen::MatrixXi E(3, 2);
  E << 0, 1, 1, 2, 2, 3;
  Eigen::SparseMatrix<double> A;
  signed_incidence_matrix_sparse(4, E, A);
  Eigen::MatrixXd expected(3, 4);
  expected << 1, -1, 0, 0,  //
      0, 1, -1, 0,          //
      0, 0, 1, -1;
  EXPECT_EQ(Eigen::MatrixXd(A), expected);
  EXPECT_EQ(A.nonZeros(), 6);  // no stored zeros
}

TEST(SignedIncidenceMatrix, SparseEqualsDenseAndGivesEdgeVectors) {
  for (const auto& mesh : wobble::testing::all_test_meshes()) {
    SCOPED_TRACE(mesh.name);
    const auto& network = mesh.network;
    const int n = static_cast<int>(network.V.rows());
    Eigen::MatrixXd dense;
    Eigen::SparseMatrix<double> sparse;
    signed_incidence_matrix_dense(n, network.E, dense);
    signed_incidence_matrix_sparse(n, network.E, sparse);
    EXPECT_EQ(Eigen::MatrixXd(sparse), dense);
    EXPECT_EQ(sparse.nonZeros(), 2 * network.E.rows());
    // (A V).row(e) = V_i − V_j: each row sums to zero and picks the spring's vector.
    const Eigen::MatrixXd edge_vectors = sparse * network.V;
    for (Eigen::Index e = 0; e < network.E.rows(); ++e) {
      EXPECT_EQ(edge_vectors.row(e),
                network.V.row(network.E(e, 0)) - network.V.row(network.E(e, 1)));
    }
    EXPECT_EQ(dense.rowwise().sum().cwiseAbs().maxCoeff(), 0.0);
  }
}

}  // namespace

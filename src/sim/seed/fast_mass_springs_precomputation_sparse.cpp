#include "fast_mass_springs_precomputation_sparse.h"

#include <vector>

#include "signed_incidence_matrix_sparse.h"

bool fast_mass_springs_precomputation_sparse(
    const Eigen::MatrixXd& V, const Eigen::MatrixXi& E, const double k, const Eigen::VectorXd& m,
    const Eigen::VectorXi& b, const double delta_t, Eigen::VectorXd& r,
    Eigen::SparseMatrix<double>& M, Eigen::SparseMatrix<double>& A, Eigen::SparseMatrix<double>& C,
    Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>& prefactorization) {
  const int n = static_cast<int>(V.rows());
  r.resize(E.rows());
  for (Eigen::Index e = 0; e < E.rows(); ++e) {
    r(e) = (V.row(E(e, 0)) - V.row(E(e, 1))).norm();
  }

  std::vector<Eigen::Triplet<double>> ijv;
  ijv.reserve(n);
  for (int i = 0; i < n; ++i) {
    ijv.emplace_back(i, i, m(i));
  }
  M.resize(n, n);
  M.setFromTriplets(ijv.begin(), ijv.end());

  signed_incidence_matrix_sparse(n, E, A);

  ijv.clear();
  for (Eigen::Index c = 0; c < b.size(); ++c) {
    ijv.emplace_back(static_cast<int>(c), b(c), 1.0);
  }
  C.resize(b.size(), n);
  C.setFromTriplets(ijv.begin(), ijv.end());

  const double w = 1e10;
  const Eigen::SparseMatrix<double> Q = k * Eigen::SparseMatrix<double>(A.transpose() * A) +
                                        M / (delta_t * delta_t) +
                                        w * Eigen::SparseMatrix<double>(C.transpose() * C);
  prefactorization.compute(Q);
  return prefactorization.info() == Eigen::Success;
}

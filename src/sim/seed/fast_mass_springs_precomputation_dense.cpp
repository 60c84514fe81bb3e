#include "fast_mass_springs_precomputation_dense.h"

#include "signed_incidence_matrix_dense.h"

bool fast_mass_springs_precomputation_dense(const Eigen::MatrixXd& V, const Eigen::MatrixXi& E,
                                            const double k, const Eigen::VectorXd& m,
                                            const Eigen::VectorXi& b, const double delta_t,
                                            Eigen::VectorXd& r, Eigen::MatrixXd& M,
                                            Eigen::MatrixXd& A, Eigen::MatrixXd& C,
                                            Eigen::LLT<Eigen::MatrixXd>& prefactorization) {
  const int n = static_cast<int>(V.rows());
  r.resize(E.rows());
  for (Eigen::Index e = 0; e < E.rows(); ++e) {
    r(e) = (V.row(E(e, 0)) - V.row(E(e, 1))).norm();
  }
  M = m.asDiagonal();
  signed_incidence_matrix_dense(n, E, A);
  C = Eigen::MatrixXd::Zero(b.size(), n);
  for (Eigen::Index c = 0; c < b.size(); ++c) {
    C(c, b(c)) = 1.0;
  }

  const double w = 1e10;
  const Eigen::MatrixXd Q = k * A.transpose() * A + M / (delta_t * delta_t) + w * C.transpose() * C;
  prefactorization.compute(Q);
  return prefactorization.info() == Eigen::Success;
}

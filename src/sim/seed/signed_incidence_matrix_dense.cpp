#include "signed_incidence_matrix_dense.h"

void signed_incidence_matrix_dense(const int n, const Eigen::MatrixXi& E, Eigen::MatrixXd& A) {
  A = Eigen::MatrixXd::Zero(E.rows(), n);
  for (Eigen::Index e = 0; e < E.rows(); ++e) {
    A(e, E(e, 0)) += 1.0;
    A(e, E(e, 1)) -= 1.0;
  }
}

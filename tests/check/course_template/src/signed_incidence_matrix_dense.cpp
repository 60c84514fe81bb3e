#include "signed_incidence_matrix_dense.h"

void signed_incidence_matrix_dense(
  const int n,
  const Eigen::MatrixXi & E,
  Eigen::MatrixXd & A)
{
  // TODO: the student's code goes here. The stub is the right shape, all zeros.
  A = Eigen::MatrixXd::Zero(E.rows(), n);
}

#ifndef SIGNED_INCIDENCE_MATRIX_DENSE_H
#define SIGNED_INCIDENCE_MATRIX_DENSE_H
#include <Eigen/Core>
// Build the signed incidence matrix of a spring network.
//
// Inputs:
//   n  number of vertices
//   E  #E by 2 list of edge indices into 0..n-1
// Outputs:
//   A  #E by n dense matrix: row e is +1 at E(e,0) and -1 at E(e,1)
void signed_incidence_matrix_dense(
  const int n,
  const Eigen::MatrixXi & E,
  Eigen::MatrixXd & A);
#endif

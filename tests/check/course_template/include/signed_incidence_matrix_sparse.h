#ifndef SIGNED_INCIDENCE_MATRIX_SPARSE_H
#define SIGNED_INCIDENCE_MATRIX_SPARSE_H
#include <Eigen/Core>
#include <Eigen/Sparse>
// The sparse form of signed_incidence_matrix_dense.
//
// Inputs:
//   n  number of vertices
//   E  #E by 2 list of edge indices into 0..n-1
// Outputs:
//   A  #E by n sparse matrix: row e is +1 at E(e,0) and -1 at E(e,1)
void signed_incidence_matrix_sparse(
  const int n,
  const Eigen::MatrixXi & E,
  Eigen::SparseMatrix<double> & A);
#endif

#ifndef WOBBLE_SIM_SIGNED_INCIDENCE_MATRIX_SPARSE_H
#define WOBBLE_SIM_SIGNED_INCIDENCE_MATRIX_SPARSE_H

#include <Eigen/Core>
#include <Eigen/Sparse>

// Construct the signed incidence matrix of a spring network as a sparse matrix: row e holds +1
// in column i and -1 in column j for the spring E(e,:) = [i j], so that (A p).row(e) = p_i - p_j.
// Built with setFromTriplets; exactly 2 nonzeros per row.
//
// Inputs:
//   n  number of vertices (#V)
//   E  #E by 2 list of edge indices into rows of V
// Outputs:
//   A  #E by n sparse signed incidence matrix
void signed_incidence_matrix_sparse(const int n, const Eigen::MatrixXi& E,
                                    Eigen::SparseMatrix<double>& A);

#endif

#ifndef WOBBLE_SIM_SIGNED_INCIDENCE_MATRIX_DENSE_H
#define WOBBLE_SIM_SIGNED_INCIDENCE_MATRIX_DENSE_H

#include <Eigen/Core>

// Construct the signed incidence matrix of a spring network: row e holds +1 in column i and -1
// in column j for the spring E(e,:) = [i j], so that (A p).row(e) = p_i - p_j.
//
// Inputs:
//   n  number of vertices (#V)
//   E  #E by 2 list of edge indices into rows of V
// Outputs:
//   A  #E by n dense signed incidence matrix
void signed_incidence_matrix_dense(const int n, const Eigen::MatrixXi& E, Eigen::MatrixXd& A);

#endif

#ifndef WOBBLE_SIM_FAST_MASS_SPRINGS_PRECOMPUTATION_SPARSE_H
#define WOBBLE_SIM_FAST_MASS_SPRINGS_PRECOMPUTATION_SPARSE_H

#include <Eigen/Core>
#include <Eigen/Sparse>

// Precompute the matrices and the sparse Cholesky factorization used by
// fast_mass_springs_step_sparse (Liu et al. 2013). Same as the dense version, but every matrix
// is sparse and built with setFromTriplets:
//
//   Q = k AᵀA + M/Δt² + w CᵀC,   w = 1e10
//
// Inputs:
//   V        #V by 3 list of rest vertex positions (also the pin targets)
//   E        #E by 2 list of edge indices into rows of V
//   k        spring stiffness (N/m)
//   m        #V list of vertex masses (kg)
//   b        #b list of indices of pinned vertices into rows of V
//   delta_t  time step (s)
// Outputs:
//   r                 #E list of edge rest lengths ‖V_i − V_j‖
//   M                 #V by #V sparse diagonal mass matrix
//   A                 #E by #V sparse signed incidence matrix
//   C                 #b by #V sparse selection matrix: C(c, b(c)) = 1
//   prefactorization  SimplicialLLT of Q (fill-reducing AMD ordering)
// Returns true when the factorization succeeded.
bool fast_mass_springs_precomputation_sparse(
    const Eigen::MatrixXd& V, const Eigen::MatrixXi& E, const double k, const Eigen::VectorXd& m,
    const Eigen::VectorXi& b, const double delta_t, Eigen::VectorXd& r,
    Eigen::SparseMatrix<double>& M, Eigen::SparseMatrix<double>& A, Eigen::SparseMatrix<double>& C,
    Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>& prefactorization);

#endif

#ifndef WOBBLE_SIM_FAST_MASS_SPRINGS_STEP_SPARSE_H
#define WOBBLE_SIM_FAST_MASS_SPRINGS_STEP_SPARSE_H

#include <Eigen/Core>
#include <Eigen/Sparse>

// Advance a mass-spring network one time step with 50 local-global iterations of Liu et al.
// 2013, using the sparse matrices from fast_mass_springs_precomputation_sparse. The step
// minimizes
//
//   ½k Σ(‖pᵢ−pⱼ‖−rᵢⱼ)² + (1/2Δt²)‖p − 2pᵗ + pᵗ⁻ᐞᵗ‖²_M − pᵀf_ext + (w/2)‖Cp − CV‖²
//
//   local:  d_e = r_e (p_i − p_j)/‖p_i − p_j‖          for every spring e = [i j]
//   global: Q p = k Aᵀd + y,  y = M(2pᵗ − pᵗ⁻ᐞᵗ)/Δt² + f_ext + w CᵀC V
//
// Inputs:
//   V                 #V by 3 list of rest vertex positions (also the pin targets)
//   E                 #E by 2 list of edge indices into rows of V
//   k                 spring stiffness (N/m)
//   b                 #b list of indices of pinned vertices into rows of V
//   delta_t           time step (s)
//   fext              #V by 3 list of external forces (N)
//   r                 #E list of edge rest lengths
//   M                 #V by #V sparse diagonal mass matrix
//   A                 #E by #V sparse signed incidence matrix
//   C                 #b by #V sparse pinned-vertex selection matrix
//   prefactorization  SimplicialLLT of Q = k AᵀA + M/Δt² + w CᵀC
//   Uprev             #V by 3 list of positions at the previous time step
//   Ucur              #V by 3 list of positions at the current time step (the initial guess)
// Outputs:
//   Unext             #V by 3 list of positions at the next time step
void fast_mass_springs_step_sparse(
    const Eigen::MatrixXd& V, const Eigen::MatrixXi& E, const double k, const Eigen::VectorXi& b,
    const double delta_t, const Eigen::MatrixXd& fext, const Eigen::VectorXd& r,
    const Eigen::SparseMatrix<double>& M, const Eigen::SparseMatrix<double>& A,
    const Eigen::SparseMatrix<double>& C,
    const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>& prefactorization,
    const Eigen::MatrixXd& Uprev, const Eigen::MatrixXd& Ucur, Eigen::MatrixXd& Unext);

#endif

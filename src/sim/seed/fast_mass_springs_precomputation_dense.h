#ifndef WOBBLE_SIM_FAST_MASS_SPRINGS_PRECOMPUTATION_DENSE_H
#define WOBBLE_SIM_FAST_MASS_SPRINGS_PRECOMPUTATION_DENSE_H

#include <Eigen/Cholesky>
#include <Eigen/Core>

// Precompute the matrices and the Cholesky factorization used by fast_mass_springs_step_dense
// (Liu et al. 2013, "Fast Simulation of Mass-Spring Systems"), with dense matrices:
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
//   M                 #V by #V diagonal mass matrix
//   A                 #E by #V signed incidence matrix
//   C                 #b by #V selection matrix: C(c, b(c)) = 1
//   prefactorization  LLT of Q
// Returns true when the factorization succeeded.
bool fast_mass_springs_precomputation_dense(const Eigen::MatrixXd& V, const Eigen::MatrixXi& E,
                                            const double k, const Eigen::VectorXd& m,
                                            const Eigen::VectorXi& b, const double delta_t,
                                            Eigen::VectorXd& r, Eigen::MatrixXd& M,
                                            Eigen::MatrixXd& A, Eigen::MatrixXd& C,
                                            Eigen::LLT<Eigen::MatrixXd>& prefactorization);

#endif

#ifndef FAST_MASS_SPRINGS_PRECOMPUTATION_DENSE_H
#define FAST_MASS_SPRINGS_PRECOMPUTATION_DENSE_H
#include <Eigen/Core>
// Everything a time step of the mass-spring system can compute once: rest lengths, the mass,
// incidence and selection matrices, and a factorization of the step's quadratic matrix.
// (Eigen::LLT is only declared by <Eigen/Core>; the .cpp includes <Eigen/Dense>.)
//
// Inputs:
//   V        #V by 3 vertex positions
//   E        #E by 2 edge indices into rows of V
//   k        spring stiffness
//   m        #V masses
//   b        #b pinned vertices as indices into rows of V
//   delta_t  time step in seconds
// Outputs:
//   r        #E rest lengths
//   M        #V by #V mass matrix
//   A        #E by #V signed incidence matrix
//   C        #b by #V selection matrix
//   prefactorization  LLT of the quadratic matrix
bool fast_mass_springs_precomputation_dense(
  const Eigen::MatrixXd & V,
  const Eigen::MatrixXi & E,
  const double k,
  const Eigen::VectorXd & m,
  const Eigen::VectorXi & b,
  const double delta_t,
  Eigen::VectorXd & r,
  Eigen::MatrixXd & M,
  Eigen::MatrixXd & A,
  Eigen::MatrixXd & C,
  Eigen::LLT<Eigen::MatrixXd> & prefactorization);
#endif

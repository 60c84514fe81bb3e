#ifndef FAST_MASS_SPRINGS_STEP_DENSE_H
#define FAST_MASS_SPRINGS_STEP_DENSE_H
#include <Eigen/Dense>
// One time step of the mass-spring system by local-global iterations.
//
// Inputs:
//   V  #V by 3 rest positions
//   E  #E by 2 edge indices into rows of V
//   k  spring stiffness
//   b  #b pinned vertices as indices into rows of V
//   delta_t  time step in seconds
//   fext  #V by 3 external forces
//   r  #E rest lengths
//   M  #V by #V mass matrix
//   A  #E by #V signed incidence matrix
//   C  #b by #V selection matrix
//   prefactorization  LLT of the quadratic matrix
//   Uprev  #V by 3 positions one step ago
//   Ucur  #V by 3 positions now
// Outputs:
//   Unext  #V by 3 positions one step on
void fast_mass_springs_step_dense(
  const Eigen::MatrixXd & V,
  const Eigen::MatrixXi & E,
  const double k,
  const Eigen::VectorXi & b,
  const double delta_t,
  const Eigen::MatrixXd & fext,
  const Eigen::VectorXd & r,
  const Eigen::MatrixXd & M,
  const Eigen::MatrixXd & A,
  const Eigen::MatrixXd & C,
  const Eigen::LLT<Eigen::MatrixXd> & prefactorization,
  const Eigen::MatrixXd & Uprev,
  const Eigen::MatrixXd & Ucur,
  Eigen::MatrixXd & Unext);
#endif

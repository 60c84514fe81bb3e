#include "fast_mass_springs_precomputation_sparse.h"
#include "signed_incidence_matrix_sparse.h"
#include <vector>

bool fast_mass_springs_precomputation_sparse(
  const Eigen::MatrixXd & V,
  const Eigen::MatrixXi & E,
  const double k,
  const Eigen::VectorXd & m,
  const Eigen::VectorXi & b,
  const double delta_t,
  Eigen::VectorXd & r,
  Eigen::SparseMatrix<double> & M,
  Eigen::SparseMatrix<double> & A,
  Eigen::SparseMatrix<double> & C,
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double> > & prefactorization)
{
  // TODO: the student's code goes here. The stub factors an identity built from triplets.
  const int n = V.rows();
  std::vector<Eigen::Triplet<double> > ijv;
  for(int i = 0; i < n; i++) ijv.emplace_back(i, i, 1.0);
  Eigen::SparseMatrix<double> Q(n, n);
  Q.setFromTriplets(ijv.begin(), ijv.end());
  prefactorization.compute(Q);
  return prefactorization.info() != Eigen::NumericalIssue;
}

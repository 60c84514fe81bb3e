#ifndef WOBBLE_SIM_CHOLESKY_SOLVER_H
#define WOBBLE_SIM_CHOLESKY_SOLVER_H

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <vector>

namespace wobble {

// Sparse Cholesky factorization Q = Pᵀ L Lᵀ P (AMD ordering) with a solve for the three
// coordinates of a #V by 3 right-hand side in one pass over L, where Eigen's solve makes one pass
// per column. The solve is what every local-global iteration pays for; reading L once instead of
// three times is most of the speed of Wobble's stepper (see the benchmark).
//
// analyze once per sparsity pattern, factorize after every change of values, solve as often as
// needed: it allocates nothing.
class CholeskySolver {
 public:
  // Symbolic analysis (ordering and elimination tree) of the pattern of the symmetric positive
  // definite Q; only its lower triangle is read.
  void analyze(const Eigen::SparseMatrix<double>& Q);
  // Numeric factorization of Q, which must have the analyzed pattern. False if Q is not
  // positive definite.
  bool factorize(const Eigen::SparseMatrix<double>& Q);
  // x = Q⁻¹ b, b and x #V by 3. x is resized only if its shape differs.
  void solve(const Eigen::MatrixXd& b, Eigen::MatrixXd& x);

  // Nonzeros of L, the diagonal included: the memory one solve streams through, twice.
  long factor_nonzeros() const {
    return static_cast<long>(rows_.size() + inverse_diagonal_.size());
  }

 private:
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> llt_;
  std::vector<int> permutation_;  // row i of the original system is row permutation_[i] of L
  // L below its diagonal, by columns: column j holds rows_[s], values_[s] for s in
  // [column_start_[j], column_start_[j + 1]).
  std::vector<int> column_start_, rows_;
  std::vector<double> values_, inverse_diagonal_;
  std::vector<double> work_;  // #V by 4 (x, y, z, padding): the three coordinates side by side
};

}  // namespace wobble

#endif

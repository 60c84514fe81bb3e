#include "cholesky_solver.h"

namespace wobble {

void CholeskySolver::analyze(const Eigen::SparseMatrix<double>& Q) {
  llt_.analyzePattern(Q);
  const Eigen::Index n = Q.rows();
  permutation_.resize(n);
  const auto& indices = llt_.permutationP().indices();
  for (Eigen::Index i = 0; i < n; ++i)
    permutation_[i] = indices(i);
  work_.assign(4 * n, 0.0);
}

bool CholeskySolver::factorize(const Eigen::SparseMatrix<double>& Q) {
  llt_.factorize(Q);
  if (llt_.info() != Eigen::Success) return false;
  // Copy L out of Eigen's storage into plain arrays with the diagonal apart (inverted, so the
  // solve multiplies), which is all the solve reads.
  const Eigen::SparseMatrix<double>& L = llt_.matrixL().nestedExpression();
  const Eigen::Index n = L.cols();
  column_start_.resize(n + 1);
  inverse_diagonal_.resize(n);
  rows_.clear();
  values_.clear();
  rows_.reserve(L.nonZeros());
  values_.reserve(L.nonZeros());
  for (Eigen::Index j = 0; j < n; ++j) {
    column_start_[j] = static_cast<int>(rows_.size());
    for (Eigen::SparseMatrix<double>::InnerIterator it(L, j); it; ++it) {
      if (it.row() == j) {
        inverse_diagonal_[j] = 1.0 / it.value();
      } else if (it.row() > j) {
        rows_.push_back(static_cast<int>(it.row()));
        values_.push_back(it.value());
      }
    }
  }
  column_start_[n] = static_cast<int>(rows_.size());
  return true;
}

void CholeskySolver::solve(const Eigen::MatrixXd& b, Eigen::MatrixXd& x) {
  const Eigen::Index n = static_cast<Eigen::Index>(permutation_.size());
  double* w = work_.data();
  for (Eigen::Index i = 0; i < n; ++i) {
    double* row = w + 4 * permutation_[i];
    row[0] = b(i, 0);
    row[1] = b(i, 1);
    row[2] = b(i, 2);
  }
  // Forward: L z = P b, column by column; each column's value is used on all three coordinates
  // while it is in a register.
  for (Eigen::Index j = 0; j < n; ++j) {
    double* wj = w + 4 * j;
    const double d = inverse_diagonal_[j];
    const double z0 = wj[0] * d, z1 = wj[1] * d, z2 = wj[2] * d;
    wj[0] = z0;
    wj[1] = z1;
    wj[2] = z2;
    for (int s = column_start_[j]; s < column_start_[j + 1]; ++s) {
      double* wi = w + 4 * rows_[s];
      const double v = values_[s];
      wi[0] -= v * z0;
      wi[1] -= v * z1;
      wi[2] -= v * z2;
    }
  }
  // Backward: Lᵀ u = z, from the last row up; row j of Lᵀ is column j of L.
  for (Eigen::Index j = n - 1; j >= 0; --j) {
    double* wj = w + 4 * j;
    double s0 = wj[0], s1 = wj[1], s2 = wj[2];
    for (int s = column_start_[j]; s < column_start_[j + 1]; ++s) {
      const double* wi = w + 4 * rows_[s];
      const double v = values_[s];
      s0 -= v * wi[0];
      s1 -= v * wi[1];
      s2 -= v * wi[2];
    }
    const double d = inverse_diagonal_[j];
    wj[0] = s0 * d;
    wj[1] = s1 * d;
    wj[2] = s2 * d;
  }
  if (x.rows() != n || x.cols() != 3) x.resize(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double* row = w + 4 * permutation_[i];
    x(i, 0) = row[0];
    x(i, 1) = row[1];
    x(i, 2) = row[2];
  }
}

}  // namespace wobble

#include "system_matrix.h"

#include <algorithm>
#include <stdexcept>

#include "damped_inertia.h"

namespace wobble {

// Built column by column straight into compressed storage: setFromTriplets on the 1.6 million
// triplets of the 256×256 cloth took 40–50 ms.
Eigen::SparseMatrix<double> spring_laplacian(const Eigen::MatrixXi& E, Eigen::Index n) {
  // Each column's entries, unsorted: the diagonal first, then one -1 per spring.
  std::vector<int> start(n + 1, 0);
  for (Eigen::Index e = 0; e < E.rows(); ++e) {
    ++start[E(e, 0) + 1];
    ++start[E(e, 1) + 1];
  }
  for (Eigen::Index i = 0; i < n; ++i)
    start[i + 1] += start[i] + 1;
  std::vector<int> rows(start[n]), next(start.begin(), start.end() - 1);
  std::vector<double> diagonal(n, 0.0);
  for (Eigen::Index i = 0; i < n; ++i)
    rows[next[i]++] = static_cast<int>(i);
  for (Eigen::Index e = 0; e < E.rows(); ++e) {
    const int i = E(e, 0), j = E(e, 1);
    rows[next[i]++] = j;
    rows[next[j]++] = i;
    diagonal[i] += 1.0;
    diagonal[j] += 1.0;
  }
  // Sorted, repeats merged, into the matrix's own arrays.
  Eigen::SparseMatrix<double> L(n, n);
  L.resizeNonZeros(start[n]);
  int* outer = L.outerIndexPtr();
  int* inner = L.innerIndexPtr();
  double* value = L.valuePtr();
  int stored = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    outer[i] = stored;
    std::sort(rows.begin() + start[i], rows.begin() + start[i + 1]);
    for (int s = start[i]; s < start[i + 1]; ++s) {
      const int row = rows[s];
      const double v = row == i ? diagonal[i] : -1.0;
      if (stored > outer[i] && inner[stored - 1] == row) {
        value[stored - 1] += v;
      } else {
        inner[stored] = row;
        value[stored++] = v;
      }
    }
  }
  outer[n] = stored;
  L.resizeNonZeros(stored);
  return L;
}

SystemMatrix::SystemMatrix(const Eigen::MatrixXi& E, Eigen::Index n)
    : laplacian_(spring_laplacian(E, n)), Q_(laplacian_) {
  find_diagonal();
}

void SystemMatrix::find_diagonal() {
  const Eigen::Index n = Q_.rows();
  diagonal_slot_.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const int* rows = Q_.innerIndexPtr();
    for (Eigen::Index s = Q_.outerIndexPtr()[i]; s < Q_.outerIndexPtr()[i + 1]; ++s) {
      if (rows[s] == i) diagonal_slot_[i] = s;
    }
  }
}

bool SystemMatrix::set_terms_matrix(const Eigen::SparseMatrix<double>& K) {
  terms_values_.clear();
  if (K.nonZeros() == 0) return false;
  // Widen the pattern by K's entries that AᵀA does not have (stored as zeros in AᵀA).
  Eigen::SparseMatrix<double> pattern = K;
  for (Eigen::Index s = 0; s < pattern.nonZeros(); ++s)
    pattern.valuePtr()[s] = 0.0;
  pattern += laplacian_;
  pattern.makeCompressed();
  const bool grew = pattern.nonZeros() != laplacian_.nonZeros();
  if (grew) {
    laplacian_ = pattern;
    Q_ = laplacian_;
    find_diagonal();
  }
  // K's values at Q's slots.
  terms_values_.assign(Q_.nonZeros(), 0.0);
  for (Eigen::Index column = 0; column < K.outerSize(); ++column) {
    Eigen::Index s = Q_.outerIndexPtr()[column];
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, column); it; ++it) {
      while (Q_.innerIndexPtr()[s] != it.row())
        ++s;
      terms_values_[s] += it.value();
    }
  }
  return grew;
}

void SystemMatrix::analyze() {
  solver_.analyze(Q_);
  ++symbolic_analyses_;
}

void SystemMatrix::refactorize(double k, double dt, double damping, const Eigen::VectorXd& m,
                               const Eigen::VectorXd& terms_diagonal) {
  // Q = k AᵀA + K + (1 + cΔt)M/Δt² + D, written into the fixed pattern.
  const double* laplacian = laplacian_.valuePtr();
  double* q = Q_.valuePtr();
  for (Eigen::Index s = 0; s < Q_.nonZeros(); ++s)
    q[s] = k * laplacian[s];
  for (std::size_t s = 0; s < terms_values_.size(); ++s)
    q[s] += terms_values_[s];
  // Damping scales the inertia term by (1 + cΔt).
  const double inertia = inertia_scale(dt, damping);
  const bool terms = terms_diagonal.size() == static_cast<Eigen::Index>(diagonal_slot_.size());
  for (std::size_t i = 0; i < diagonal_slot_.size(); ++i)
    q[diagonal_slot_[i]] += m(i) * inertia + (terms ? terms_diagonal(i) : 0.0);
  ++numeric_factorizations_;
  if (!solver_.factorize(Q_)) throw std::runtime_error("the Cholesky factorization of Q failed");
}

Eigen::VectorXd SystemMatrix::base_diagonal(double k, double dt, double damping,
                                            const Eigen::VectorXd& m) const {
  const double inertia = inertia_scale(dt, damping);
  Eigen::VectorXd diagonal(diagonal_slot_.size());
  for (std::size_t i = 0; i < diagonal_slot_.size(); ++i)
    diagonal(i) = k * laplacian_.valuePtr()[diagonal_slot_[i]] + m(i) * inertia;
  return diagonal;
}

}  // namespace wobble

#ifndef WOBBLE_SIM_SOLVER_SYSTEM_MATRIX_H
#define WOBBLE_SIM_SOLVER_SYSTEM_MATRIX_H

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "cholesky_solver.h"

namespace wobble {

// AᵀA for the springs E (#E by 2, no spring from a vertex to itself), #V by #V: +1 at (i,i) and
// (j,j) and −1 at (i,j) and (j,i) for every spring, repeats summed. Every diagonal entry is
// stored, zero for a vertex without springs.
Eigen::SparseMatrix<double> spring_laplacian(const Eigen::MatrixXi& E, Eigen::Index n);

// The global step's matrix, #V by #V, and its Cholesky factorization:
//   Q = k AᵀA + (1 + cΔt)M/Δt² + K + D,  D the step's terms' diagonal (w CᵀC for the pins, ...),
//   K the terms' fixed matrix (the volume term's; none for most scenes)
// in a pattern that never changes (AᵀA's, its diagonal always stored; a K outside it widens it
// once), so that k, Δt, damping, masses and pins only ever change values: one symbolic analysis
// serves every factorization.
class SystemMatrix {
 public:
  SystemMatrix() = default;
  // E  #E by 2 springs;  n  #V. Builds the pattern; analyze() before the first refactorize().
  SystemMatrix(const Eigen::MatrixXi& E, Eigen::Index n);

  // The terms' fixed matrix K (#V by #V, symmetric), in Q from the next refactorize(); no entries
  // for none, which leaves Q exactly as without it. Returns whether Q's pattern had to grow to
  // hold K (then analyze() again before refactorizing).
  bool set_terms_matrix(const Eigen::SparseMatrix<double>& K);

  // The symbolic analysis of Q's pattern (throws InputError for a factor too large).
  void analyze();
  // Refill Q's values and factorize numerically. Throws std::runtime_error if Q is not positive
  // definite.
  //   m  #V masses (kg)
  //   terms_diagonal  #V the step's terms' weights (w CᵀC for the pins, contact's κ), or empty
  //                   for none
  void refactorize(double k, double dt, double damping, const Eigen::VectorXd& m,
                   const Eigen::VectorXd& terms_diagonal = Eigen::VectorXd());
  // k·AᵀAᵢᵢ + (1 + cΔt)mᵢ/Δt² for each vertex (#V): Q's diagonal without pins or contact.
  Eigen::VectorXd base_diagonal(double k, double dt, double damping,
                                const Eigen::VectorXd& m) const;

  const Eigen::SparseMatrix<double>& Q() const { return Q_; }
  // Q's factorization: solve(b, x) gives x = Q⁻¹ b for #V by 3 b.
  CholeskySolver& cholesky() { return solver_; }
  const CholeskySolver& cholesky() const { return solver_; }
  int symbolic_analyses() const { return symbolic_analyses_; }
  int numeric_factorizations() const { return numeric_factorizations_; }

 private:
  void find_diagonal();

  Eigen::SparseMatrix<double> laplacian_;    // AᵀA with every diagonal entry stored
  Eigen::SparseMatrix<double> Q_;            // same pattern as laplacian_
  std::vector<Eigen::Index> diagonal_slot_;  // index of Q(i,i) in Q_.valuePtr()
  std::vector<double> terms_values_;         // K in Q_'s pattern; empty for none
  CholeskySolver solver_;
  int symbolic_analyses_ = 0;
  int numeric_factorizations_ = 0;
};

}  // namespace wobble

#endif

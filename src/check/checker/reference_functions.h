#ifndef WOBBLE_CHECK_REFERENCE_FUNCTIONS_H
#define WOBBLE_CHECK_REFERENCE_FUNCTIONS_H

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Sparse>

// Wobble's own six assignment functions (src/sim/seed) under other names: the checker's oracle.
// scripts/check-assignment.sh compiles the seed's sources a second time with
// -Dsigned_incidence_matrix_dense=reference_signed_incidence_matrix_dense (and so on for all
// six), which renames their definitions and the calls between them alike, so these never clash
// with the student's functions linked into the same checker. The signatures, shapes and units
// are those of src/sim/seed/*.h; a mismatch here is a link error, never a silent difference.

void reference_signed_incidence_matrix_dense(const int n, const Eigen::MatrixXi& E,
                                             Eigen::MatrixXd& A);

void reference_signed_incidence_matrix_sparse(const int n, const Eigen::MatrixXi& E,
                                              Eigen::SparseMatrix<double>& A);

bool reference_fast_mass_springs_precomputation_dense(
    const Eigen::MatrixXd& V, const Eigen::MatrixXi& E, const double k, const Eigen::VectorXd& m,
    const Eigen::VectorXi& b, const double delta_t, Eigen::VectorXd& r, Eigen::MatrixXd& M,
    Eigen::MatrixXd& A, Eigen::MatrixXd& C, Eigen::LLT<Eigen::MatrixXd>& prefactorization);

bool reference_fast_mass_springs_precomputation_sparse(
    const Eigen::MatrixXd& V, const Eigen::MatrixXi& E, const double k, const Eigen::VectorXd& m,
    const Eigen::VectorXi& b, const double delta_t, Eigen::VectorXd& r,
    Eigen::SparseMatrix<double>& M, Eigen::SparseMatrix<double>& A, Eigen::SparseMatrix<double>& C,
    Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>& prefactorization);

void reference_fast_mass_springs_step_dense(const Eigen::MatrixXd& V, const Eigen::MatrixXi& E,
                                            const double k, const Eigen::VectorXi& b,
                                            const double delta_t, const Eigen::MatrixXd& fext,
                                            const Eigen::VectorXd& r, const Eigen::MatrixXd& M,
                                            const Eigen::MatrixXd& A, const Eigen::MatrixXd& C,
                                            const Eigen::LLT<Eigen::MatrixXd>& prefactorization,
                                            const Eigen::MatrixXd& Uprev,
                                            const Eigen::MatrixXd& Ucur, Eigen::MatrixXd& Unext);

void reference_fast_mass_springs_step_sparse(
    const Eigen::MatrixXd& V, const Eigen::MatrixXi& E, const double k, const Eigen::VectorXi& b,
    const double delta_t, const Eigen::MatrixXd& fext, const Eigen::VectorXd& r,
    const Eigen::SparseMatrix<double>& M, const Eigen::SparseMatrix<double>& A,
    const Eigen::SparseMatrix<double>& C,
    const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>& prefactorization,
    const Eigen::MatrixXd& Uprev, const Eigen::MatrixXd& Ucur, Eigen::MatrixXd& Unext);

#endif

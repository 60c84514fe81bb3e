#ifndef WOBBLE_CHECK_COURSE_CALL_H
#define WOBBLE_CHECK_COURSE_CALL_H

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Sparse>

// Each of the six assignment functions called as the course calls it: its main.cpp for the
// precomputations and steps, a precomputation for the incidence matrices. course_call.cpp is
// compiled once per function against the submission's own header, so whatever signature that
// header declares is accepted when the course's call compiles with it: an extra defaulted
// argument, a value or non-const reference parameter, another order of const. The inputs are
// copied into non-const locals first, as main.cpp holds them, so a function that writes to an
// input cannot change the checker's data. The prefactorization and the outputs are the caller's
// own objects (a sparse factorization cannot be copied): give the student's call objects of its
// own. Shapes and units are those of src/sim/seed/*.h; Unext comes in as the caller set it (the
// course's main.cpp passes Unext already equal to Ucur).

void course_call_signed_incidence_matrix_dense(int n, const Eigen::MatrixXi& E, Eigen::MatrixXd& A);

void course_call_signed_incidence_matrix_sparse(int n, const Eigen::MatrixXi& E,
                                                Eigen::SparseMatrix<double>& A);

bool course_call_fast_mass_springs_precomputation_dense(
    const Eigen::MatrixXd& V, const Eigen::MatrixXi& E, double k, const Eigen::VectorXd& m,
    const Eigen::VectorXi& b, double delta_t, Eigen::VectorXd& r, Eigen::MatrixXd& M,
    Eigen::MatrixXd& A, Eigen::MatrixXd& C, Eigen::LLT<Eigen::MatrixXd>& prefactorization);

bool course_call_fast_mass_springs_precomputation_sparse(
    const Eigen::MatrixXd& V, const Eigen::MatrixXi& E, double k, const Eigen::VectorXd& m,
    const Eigen::VectorXi& b, double delta_t, Eigen::VectorXd& r, Eigen::SparseMatrix<double>& M,
    Eigen::SparseMatrix<double>& A, Eigen::SparseMatrix<double>& C,
    Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>& prefactorization);

void course_call_fast_mass_springs_step_dense(const Eigen::MatrixXd& V, const Eigen::MatrixXi& E,
                                              double k, const Eigen::VectorXi& b, double delta_t,
                                              const Eigen::MatrixXd& fext, const Eigen::VectorXd& r,
                                              const Eigen::MatrixXd& M, const Eigen::MatrixXd& A,
                                              const Eigen::MatrixXd& C,
                                              Eigen::LLT<Eigen::MatrixXd>& prefactorization,
                                              const Eigen::MatrixXd& Uprev,
                                              const Eigen::MatrixXd& Ucur, Eigen::MatrixXd& Unext);

void course_call_fast_mass_springs_step_sparse(
    const Eigen::MatrixXd& V, const Eigen::MatrixXi& E, double k, const Eigen::VectorXi& b,
    double delta_t, const Eigen::MatrixXd& fext, const Eigen::VectorXd& r,
    const Eigen::SparseMatrix<double>& M, const Eigen::SparseMatrix<double>& A,
    const Eigen::SparseMatrix<double>& C,
    Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>& prefactorization,
    const Eigen::MatrixXd& Uprev, const Eigen::MatrixXd& Ucur, Eigen::MatrixXd& Unext);

#endif

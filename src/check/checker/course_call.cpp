// One course call site per build: scripts/check-assignment.sh compiles this file at the end of
// each student file, in one translation unit (course_call.h first, then the student's file, then
// this with -DWOBBLE_COURSE_CALL_<function>), with the submission's include folders ahead of
// src/sim/seed, so "<function>.h" below is the submission's own header when it has one. The
// call is spelled as the course spells it (main.cpp for the precomputations and steps), with
// arguments of the kinds it passes: non-const lvalues, a const delta_t, a const copy of U as
// Ucur. Every name here has a call_ or given_ prefix, so a student's own macro (one writes
// `#define w 1e10`) cannot reach into it. The script then checks that the submission's object
// defines the function this call names, so the reference's copy of it can never stand in.
#include "course_call.h"

#if defined(WOBBLE_COURSE_CALL_signed_incidence_matrix_dense)
#include "signed_incidence_matrix_dense.h"

void course_call_signed_incidence_matrix_dense(int given_n, const Eigen::MatrixXi& given_E,
                                               Eigen::MatrixXd& call_A) {
  // As a precomputation calls it: its own n, its const E, its output A.
  const int call_n = given_n;
  const Eigen::MatrixXi& call_E = given_E;
  signed_incidence_matrix_dense(call_n, call_E, call_A);
}

#elif defined(WOBBLE_COURSE_CALL_signed_incidence_matrix_sparse)
#include "signed_incidence_matrix_sparse.h"

void course_call_signed_incidence_matrix_sparse(int given_n, const Eigen::MatrixXi& given_E,
                                                Eigen::SparseMatrix<double>& call_A) {
  const int call_n = given_n;
  const Eigen::MatrixXi& call_E = given_E;
  signed_incidence_matrix_sparse(call_n, call_E, call_A);
}

#elif defined(WOBBLE_COURSE_CALL_fast_mass_springs_precomputation_dense)
#include "fast_mass_springs_precomputation_dense.h"

bool course_call_fast_mass_springs_precomputation_dense(
    const Eigen::MatrixXd& given_V, const Eigen::MatrixXi& given_E, double given_k,
    const Eigen::VectorXd& given_m, const Eigen::VectorXi& given_b, double given_delta_t,
    Eigen::VectorXd& call_r, Eigen::MatrixXd& call_M, Eigen::MatrixXd& call_A,
    Eigen::MatrixXd& call_C, Eigen::LLT<Eigen::MatrixXd>& call_prefactorization) {
  Eigen::MatrixXd call_V = given_V;
  Eigen::MatrixXi call_E = given_E;
  double call_k = given_k;
  Eigen::VectorXd call_m = given_m;
  Eigen::VectorXi call_b = given_b;
  const double call_delta_t = given_delta_t;
  return fast_mass_springs_precomputation_dense(call_V, call_E, call_k, call_m, call_b,
                                                call_delta_t, call_r, call_M, call_A, call_C,
                                                call_prefactorization);
}

#elif defined(WOBBLE_COURSE_CALL_fast_mass_springs_precomputation_sparse)
#include "fast_mass_springs_precomputation_sparse.h"

bool course_call_fast_mass_springs_precomputation_sparse(
    const Eigen::MatrixXd& given_V, const Eigen::MatrixXi& given_E, double given_k,
    const Eigen::VectorXd& given_m, const Eigen::VectorXi& given_b, double given_delta_t,
    Eigen::VectorXd& call_r, Eigen::SparseMatrix<double>& call_M,
    Eigen::SparseMatrix<double>& call_A, Eigen::SparseMatrix<double>& call_C,
    Eigen::SimplicialLLT<Eigen::SparseMatrix<double> >& call_prefactorization) {
  Eigen::MatrixXd call_V = given_V;
  Eigen::MatrixXi call_E = given_E;
  double call_k = given_k;
  Eigen::VectorXd call_m = given_m;
  Eigen::VectorXi call_b = given_b;
  const double call_delta_t = given_delta_t;
  return fast_mass_springs_precomputation_sparse(call_V, call_E, call_k, call_m, call_b,
                                                 call_delta_t, call_r, call_M, call_A, call_C,
                                                 call_prefactorization);
}

#elif defined(WOBBLE_COURSE_CALL_fast_mass_springs_step_dense)
#include "fast_mass_springs_step_dense.h"

void course_call_fast_mass_springs_step_dense(
    const Eigen::MatrixXd& given_V, const Eigen::MatrixXi& given_E, double given_k,
    const Eigen::VectorXi& given_b, double given_delta_t, const Eigen::MatrixXd& given_fext,
    const Eigen::VectorXd& given_r, const Eigen::MatrixXd& given_M, const Eigen::MatrixXd& given_A,
    const Eigen::MatrixXd& given_C, Eigen::LLT<Eigen::MatrixXd>& call_prefactorization,
    const Eigen::MatrixXd& given_Uprev, const Eigen::MatrixXd& Ucur_in, Eigen::MatrixXd& call_U) {
  Eigen::MatrixXd call_V = given_V;
  Eigen::MatrixXi call_E = given_E;
  double call_k = given_k;
  Eigen::VectorXi call_b = given_b;
  const double call_delta_t = given_delta_t;
  Eigen::MatrixXd call_fext = given_fext;
  Eigen::VectorXd call_r = given_r;
  Eigen::MatrixXd call_M = given_M, call_A = given_A, call_C = given_C;
  Eigen::MatrixXd call_Uprev = given_Uprev;
  const Eigen::MatrixXd call_U_stash = Ucur_in;
  fast_mass_springs_step_dense(call_V, call_E, call_k, call_b, call_delta_t, call_fext, call_r,
                               call_M, call_A, call_C, call_prefactorization, call_Uprev,
                               call_U_stash, call_U);
}

#elif defined(WOBBLE_COURSE_CALL_fast_mass_springs_step_sparse)
#include "fast_mass_springs_step_sparse.h"

void course_call_fast_mass_springs_step_sparse(
    const Eigen::MatrixXd& given_V, const Eigen::MatrixXi& given_E, double given_k,
    const Eigen::VectorXi& given_b, double given_delta_t, const Eigen::MatrixXd& given_fext,
    const Eigen::VectorXd& given_r, const Eigen::SparseMatrix<double>& given_M,
    const Eigen::SparseMatrix<double>& given_A, const Eigen::SparseMatrix<double>& given_C,
    Eigen::SimplicialLLT<Eigen::SparseMatrix<double> >& call_prefactorization,
    const Eigen::MatrixXd& given_Uprev, const Eigen::MatrixXd& Ucur_in, Eigen::MatrixXd& call_U) {
  Eigen::MatrixXd call_V = given_V;
  Eigen::MatrixXi call_E = given_E;
  double call_k = given_k;
  Eigen::VectorXi call_b = given_b;
  const double call_delta_t = given_delta_t;
  Eigen::MatrixXd call_fext = given_fext;
  Eigen::VectorXd call_r = given_r;
  Eigen::SparseMatrix<double> call_M = given_M, call_A = given_A, call_C = given_C;
  Eigen::MatrixXd call_Uprev = given_Uprev;
  const Eigen::MatrixXd call_U_stash = Ucur_in;
  fast_mass_springs_step_sparse(call_V, call_E, call_k, call_b, call_delta_t, call_fext, call_r,
                                call_M, call_A, call_C, call_prefactorization, call_Uprev,
                                call_U_stash, call_U);
}

#else
#error "compile with -DWOBBLE_COURSE_CALL_<function> (scripts/check-assignment.sh does)"
#endif

// Weak stand-ins for the course calls (course_call.h) that a checker does not link: each checker
// holds the checks of all six functions but only its own function's course call site
// (course_call.cpp compiled for it), whose strong definition replaces the stand-in here. The
// others are never called; if one were, it throws instead of testing the wrong code.
#include <stdexcept>

#include "course_call.h"

namespace {

[[noreturn]] void not_linked(const char* function) {
  throw std::logic_error(std::string("this checker does not hold the student's ") + function +
                         " (a checker bug, please report it)");
}

}  // namespace

__attribute__((weak)) void course_call_signed_incidence_matrix_dense(int, const Eigen::MatrixXi&,
                                                                     Eigen::MatrixXd&) {
  not_linked("signed_incidence_matrix_dense");
}

__attribute__((weak)) void course_call_signed_incidence_matrix_sparse(
    int, const Eigen::MatrixXi&, Eigen::SparseMatrix<double>&) {
  not_linked("signed_incidence_matrix_sparse");
}

__attribute__((weak)) bool course_call_fast_mass_springs_precomputation_dense(
    const Eigen::MatrixXd&, const Eigen::MatrixXi&, double, const Eigen::VectorXd&,
    const Eigen::VectorXi&, double, Eigen::VectorXd&, Eigen::MatrixXd&, Eigen::MatrixXd&,
    Eigen::MatrixXd&, Eigen::LLT<Eigen::MatrixXd>&) {
  not_linked("fast_mass_springs_precomputation_dense");
}

__attribute__((weak)) bool course_call_fast_mass_springs_precomputation_sparse(
    const Eigen::MatrixXd&, const Eigen::MatrixXi&, double, const Eigen::VectorXd&,
    const Eigen::VectorXi&, double, Eigen::VectorXd&, Eigen::SparseMatrix<double>&,
    Eigen::SparseMatrix<double>&, Eigen::SparseMatrix<double>&,
    Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>&) {
  not_linked("fast_mass_springs_precomputation_sparse");
}

__attribute__((weak)) void course_call_fast_mass_springs_step_dense(
    const Eigen::MatrixXd&, const Eigen::MatrixXi&, double, const Eigen::VectorXi&, double,
    const Eigen::MatrixXd&, const Eigen::VectorXd&, const Eigen::MatrixXd&, const Eigen::MatrixXd&,
    const Eigen::MatrixXd&, Eigen::LLT<Eigen::MatrixXd>&, const Eigen::MatrixXd&,
    const Eigen::MatrixXd&, Eigen::MatrixXd&) {
  not_linked("fast_mass_springs_step_dense");
}

__attribute__((weak)) void course_call_fast_mass_springs_step_sparse(
    const Eigen::MatrixXd&, const Eigen::MatrixXi&, double, const Eigen::VectorXi&, double,
    const Eigen::MatrixXd&, const Eigen::VectorXd&, const Eigen::SparseMatrix<double>&,
    const Eigen::SparseMatrix<double>&, const Eigen::SparseMatrix<double>&,
    Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>&, const Eigen::MatrixXd&,
    const Eigen::MatrixXd&, Eigen::MatrixXd&) {
  not_linked("fast_mass_springs_step_sparse");
}

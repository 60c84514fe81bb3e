#include <Eigen/Core>
#include <Eigen/Sparse>
#include <vector>

#include "check_cases.h"
#include "compare.h"
#include "course_call.h"
#include "reference_functions.h"

CheckResult check_signed_incidence_matrix_dense(const CheckScene& scene, const CheckContext&) {
  const int n = static_cast<int>(scene.V.rows());
  Eigen::MatrixXd expected;
  reference_signed_incidence_matrix_dense(n, scene.E, expected);
  Eigen::MatrixXd A;
  if (scene.outputs_prefilled) A = Eigen::MatrixXd::Constant(scene.E.rows(), n, 7.0);
  course_call_signed_incidence_matrix_dense(n, scene.E, A);
  CheckResult result;
  result.difference =
      incidence_difference(compare_dense("A", "#E by #V", A, expected, 0.0), A, expected);
  return result;
}

CheckResult check_signed_incidence_matrix_sparse(const CheckScene& scene, const CheckContext&) {
  const int n = static_cast<int>(scene.V.rows());
  Eigen::SparseMatrix<double> expected;
  reference_signed_incidence_matrix_sparse(n, scene.E, expected);
  Eigen::SparseMatrix<double> A;
  if (scene.outputs_prefilled) {
    A.resize(scene.E.rows(), n);
    for (int e = 0; e < scene.E.rows(); ++e)
      A.insert(e, e % n) = 7.0;
  }
  course_call_signed_incidence_matrix_sparse(n, scene.E, A);
  CheckResult result;
  result.difference =
      incidence_difference(compare_sparse("A", "#E by #V", A, expected, 0.0), A, expected);
  if (result.difference.empty())
    result.difference = check_sparse_storage("A", A, 2 * scene.E.rows(), "2 per spring");
  return result;
}

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <vector>

#include "check_cases.h"
#include "compare.h"
#include "reference_functions.h"
#include "signed_incidence_matrix_dense.h"
#include "signed_incidence_matrix_sparse.h"

namespace {

const char* const kIncidenceRule = " (row e holds +1 at column E(e,0) and -1 at column E(e,1))";

}  // namespace

std::string check_signed_incidence_matrix_dense(const CheckScene& scene) {
  const int n = static_cast<int>(scene.V.rows());
  Eigen::MatrixXd expected;
  reference_signed_incidence_matrix_dense(n, scene.E, expected);
  Eigen::MatrixXd A;
  if (scene.outputs_prefilled) A = Eigen::MatrixXd::Constant(scene.E.rows(), n, 7.0);
  signed_incidence_matrix_dense(n, scene.E, A);
  const std::string difference = compare_dense("A", "#E by #V", A, expected, 0.0);
  if (!difference.empty() && A.rows() == expected.rows() && A.cols() == expected.cols())
    return difference + kIncidenceRule;
  return difference;
}

std::string check_signed_incidence_matrix_sparse(const CheckScene& scene) {
  const int n = static_cast<int>(scene.V.rows());
  Eigen::SparseMatrix<double> expected;
  reference_signed_incidence_matrix_sparse(n, scene.E, expected);
  Eigen::SparseMatrix<double> A;
  if (scene.outputs_prefilled) {
    A.resize(scene.E.rows(), n);
    for (int e = 0; e < scene.E.rows(); ++e)
      A.insert(e, e % n) = 7.0;
  }
  signed_incidence_matrix_sparse(n, scene.E, A);
  std::string difference = compare_sparse("A", "#E by #V", A, expected, 0.0);
  if (!difference.empty() && A.rows() == expected.rows() && A.cols() == expected.cols())
    return difference + kIncidenceRule;
  if (difference.empty())
    difference = check_sparse_storage("A", A, 2 * scene.E.rows(), "2 per spring");
  return difference;
}

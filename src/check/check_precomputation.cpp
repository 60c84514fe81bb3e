#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Sparse>

#include "check_cases.h"
#include "compare.h"
#include "fast_mass_springs_precomputation_dense.h"
#include "fast_mass_springs_precomputation_sparse.h"
#include "reference_functions.h"

namespace {

const char* const kQ = " (Q = k AᵀA + M/Δt² + w CᵀC, w = 1e10)";
const char* const kReferenceFailed =
    "the reference precomputation failed on this input: a checker bug, please report it";

// The prefactorization is judged by what it is for: solving Q p = rhs. The right-hand side is
// Q X for the scene's current positions X, so the answer is a pose of the scene's size and
// its tolerance is in metres like the step's.
template <typename Matrix>
Eigen::MatrixXd right_hand_side(const CheckScene& scene, const Matrix& M, const Matrix& A,
                                const Matrix& C) {
  const Matrix Q = scene.k * Matrix(A.transpose() * A) + M / (scene.delta_t * scene.delta_t) +
                   kPinWeight * Matrix(C.transpose() * C);
  return Q * scene.Ucur;
}

}  // namespace

std::string check_fast_mass_springs_precomputation_dense(const CheckScene& scene) {
  const Eigen::Index n = scene.V.rows(), springs = scene.E.rows(), pins = scene.b.size();
  Eigen::VectorXd r0;
  Eigen::MatrixXd M0, A0, C0;
  Eigen::LLT<Eigen::MatrixXd> factor0;
  if (!reference_fast_mass_springs_precomputation_dense(scene.V, scene.E, scene.k, scene.m, scene.b,
                                                        scene.delta_t, r0, M0, A0, C0, factor0))
    return kReferenceFailed;

  Eigen::VectorXd r;
  Eigen::MatrixXd M, A, C;
  Eigen::LLT<Eigen::MatrixXd> factor;
  if (scene.outputs_prefilled) {
    r = Eigen::VectorXd::Constant(springs, 7.0);
    M = Eigen::MatrixXd::Constant(n, n, 7.0);
    A = Eigen::MatrixXd::Constant(springs, n, 7.0);
    C = Eigen::MatrixXd::Constant(pins, n, 7.0);
  }
  if (!fast_mass_springs_precomputation_dense(scene.V, scene.E, scene.k, scene.m, scene.b,
                                              scene.delta_t, r, M, A, C, factor))
    return "returned false (factorization failed), but Q is positive definite";

  const double size = scene_size(scene);
  std::string difference = compare_vector("r", "#E", r, r0, kLengthTolerance * size);
  if (difference.empty())
    difference = compare_dense("M", "#V by #V", M, M0, kMassTolerance * scene.m.maxCoeff());
  if (difference.empty()) difference = compare_dense("A", "#E by #V", A, A0, 0.0);
  if (difference.empty()) difference = compare_dense("C", "#b by #V", C, C0, 0.0);
  if (!difference.empty()) return difference;

  const Eigen::MatrixXd rhs = right_hand_side(scene, M0, A0, C0);
  difference = compare_vertices("prefactorization.solve(Q·Ucur)", factor.solve(rhs),
                                factor0.solve(rhs), kPositionTolerance * size);
  return difference.empty() ? difference : difference + kQ;
}

std::string check_fast_mass_springs_precomputation_sparse(const CheckScene& scene) {
  using Sparse = Eigen::SparseMatrix<double>;
  const Eigen::Index n = scene.V.rows(), springs = scene.E.rows(), pins = scene.b.size();
  Eigen::VectorXd r0;
  Sparse M0, A0, C0;
  Eigen::SimplicialLLT<Sparse> factor0;
  if (!reference_fast_mass_springs_precomputation_sparse(
          scene.V, scene.E, scene.k, scene.m, scene.b, scene.delta_t, r0, M0, A0, C0, factor0))
    return kReferenceFailed;

  Eigen::VectorXd r;
  Sparse M, A, C;
  Eigen::SimplicialLLT<Sparse> factor;
  if (scene.outputs_prefilled) {
    r = Eigen::VectorXd::Constant(springs, 7.0);
    M = 7.0 * M0;
    A = 7.0 * A0;
    C.resize(pins, n);
    for (Eigen::Index c = 0; c < pins; ++c)
      C.insert(c, (c + 1) % n) = 7.0;
  }
  if (!fast_mass_springs_precomputation_sparse(scene.V, scene.E, scene.k, scene.m, scene.b,
                                               scene.delta_t, r, M, A, C, factor))
    return "returned false (factorization failed), but Q is positive definite";

  const double size = scene_size(scene);
  std::string difference = compare_vector("r", "#E", r, r0, kLengthTolerance * size);
  if (difference.empty())
    difference = compare_sparse("M", "#V by #V", M, M0, kMassTolerance * scene.m.maxCoeff());
  if (difference.empty()) difference = compare_sparse("A", "#E by #V", A, A0, 0.0);
  if (difference.empty()) difference = compare_sparse("C", "#b by #V", C, C0, 0.0);
  if (difference.empty()) difference = check_sparse_storage("M", M, n, "1 per vertex");
  if (difference.empty()) difference = check_sparse_storage("A", A, 2 * springs, "2 per spring");
  if (difference.empty()) difference = check_sparse_storage("C", C, pins, "1 per pin");
  if (!difference.empty()) return difference;

  const Eigen::MatrixXd rhs = right_hand_side(scene, M0, A0, C0);
  difference = compare_vertices("prefactorization.solve(Q·Ucur)", factor.solve(rhs),
                                factor0.solve(rhs), kPositionTolerance * size);
  return difference.empty() ? difference : difference + kQ;
}

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Sparse>
#include <cmath>

#include "check_cases.h"
#include "compare.h"
#include "course_call.h"
#include "pin_weight.h"
#include "reference_functions.h"

namespace {

const char* const kReferenceFailed =
    "the reference precomputation failed on this input: a checker bug, please report it";

using Sparse = Eigen::SparseMatrix<double>;

// The prefactorization is judged by what it is for: solving Q p = rhs, against the reference's
// Q built with the pin weight the student's factorization holds (pin_weight.h) when that weight
// is acceptable and the factorization has the form Q0 + w CᵀC, else with the handout's. The
// right-hand side is Q X for the scene's current positions X, so the answer is a pose of the
// scene's size and its tolerance is in metres like the step's.
template <typename Matrix, typename Factor>
void check_factorization(const CheckScene& scene, const Matrix& M0, const Matrix& A0,
                         const Matrix& C0, const Factor& factor, CheckResult& result) {
  const Matrix Q0 = quadratic_without_pins(scene.k, scene.delta_t, M0, A0);
  const bool pinned = scene.b.size() > 0;
  double weight = kHandoutPinWeight;
  std::string weight_words;
  if (pinned) {
    const FactoredPinWeight found = factored_pin_weight(factor, Q0, C0);
    if (found.fits) result.pin_weight = found.w;
    if (found.fits && acceptable_pin_weight(found.w)) {
      // The handout's weight, found to rounding, is the handout's.
      const bool handout = std::abs(found.w - kHandoutPinWeight) <= 1e-9 * kHandoutPinWeight;
      weight = handout ? kHandoutPinWeight : found.w;
      result.pin_weight = weight;
    } else if (found.fits && found.w == 0) {
      weight_words = "; its Q has no pin term w CᵀC";
    } else if (found.fits) {
      weight_words = "; its Q holds the pins with w = " + pin_weight_text(found.w) +
                     ", outside the weights accepted (" + pin_weight_text(kLightestPinWeight) +
                     " to " + pin_weight_text(kHeaviestPinWeight) + ")";
    }
  }
  const Matrix Q = Q0 + weight * Matrix(C0.transpose() * C0);
  const Factor reference(Q);
  const Eigen::MatrixXd rhs = Q * scene.Ucur;
  result.difference =
      compare_vertices("prefactorization.solve(Q·Ucur)", factor.solve(rhs), reference.solve(rhs),
                       kPositionTolerance * scene_size(scene));
  if (!result.difference.empty())
    result.difference +=
        " (Q = k AᵀA + M/Δt² + w CᵀC, w = " + pin_weight_text(weight) + ")" + weight_words;
}

}  // namespace

CheckResult check_fast_mass_springs_precomputation_dense(const CheckScene& scene,
                                                         const CheckContext&) {
  const Eigen::Index n = scene.V.rows(), springs = scene.E.rows(), pins = scene.b.size();
  CheckResult result;
  Eigen::VectorXd r0;
  Eigen::MatrixXd M0, A0, C0;
  Eigen::LLT<Eigen::MatrixXd> factor0;
  if (!reference_fast_mass_springs_precomputation_dense(scene.V, scene.E, scene.k, scene.m, scene.b,
                                                        scene.delta_t, r0, M0, A0, C0, factor0)) {
    result.difference = kReferenceFailed;
    return result;
  }

  Eigen::VectorXd r;
  Eigen::MatrixXd M, A, C;
  Eigen::LLT<Eigen::MatrixXd> factor;
  if (scene.outputs_prefilled) {
    r = Eigen::VectorXd::Constant(springs, 7.0);
    M = Eigen::MatrixXd::Constant(n, n, 7.0);
    A = Eigen::MatrixXd::Constant(springs, n, 7.0);
    C = Eigen::MatrixXd::Constant(pins, n, 7.0);
  }
  if (!course_call_fast_mass_springs_precomputation_dense(
          scene.V, scene.E, scene.k, scene.m, scene.b, scene.delta_t, r, M, A, C, factor)) {
    result.difference = "returned false (factorization failed), but Q is positive definite";
    return result;
  }

  const double size = scene_size(scene);
  std::string& difference = result.difference;
  difference = compare_vector("r", "#E", r, r0, kLengthTolerance * size);
  if (difference.empty())
    difference = compare_dense("M", "#V by #V", M, M0, kMassTolerance * scene.m.maxCoeff());
  if (difference.empty())
    difference = incidence_difference(compare_dense("A", "#E by #V", A, A0, 0.0), A, A0);
  if (difference.empty()) difference = compare_dense("C", "#b by #V", C, C0, 0.0);
  if (difference.empty()) check_factorization(scene, M0, A0, C0, factor, result);
  return result;
}

CheckResult check_fast_mass_springs_precomputation_sparse(const CheckScene& scene,
                                                          const CheckContext&) {
  const Eigen::Index n = scene.V.rows(), springs = scene.E.rows(), pins = scene.b.size();
  CheckResult result;
  Eigen::VectorXd r0;
  Sparse M0, A0, C0;
  Eigen::SimplicialLLT<Sparse> factor0;
  if (!reference_fast_mass_springs_precomputation_sparse(
          scene.V, scene.E, scene.k, scene.m, scene.b, scene.delta_t, r0, M0, A0, C0, factor0)) {
    result.difference = kReferenceFailed;
    return result;
  }

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
  if (!course_call_fast_mass_springs_precomputation_sparse(
          scene.V, scene.E, scene.k, scene.m, scene.b, scene.delta_t, r, M, A, C, factor)) {
    result.difference = "returned false (factorization failed), but Q is positive definite";
    return result;
  }

  const double size = scene_size(scene);
  std::string& difference = result.difference;
  difference = compare_vector("r", "#E", r, r0, kLengthTolerance * size);
  if (difference.empty())
    difference = compare_sparse("M", "#V by #V", M, M0, kMassTolerance * scene.m.maxCoeff());
  if (difference.empty())
    difference = incidence_difference(compare_sparse("A", "#E by #V", A, A0, 0.0), A, A0);
  if (difference.empty()) difference = compare_sparse("C", "#b by #V", C, C0, 0.0);
  if (difference.empty()) difference = check_sparse_storage("M", M, n, "1 per vertex");
  if (difference.empty()) difference = check_sparse_storage("A", A, 2 * springs, "2 per spring");
  if (difference.empty()) difference = check_sparse_storage("C", C, pins, "1 per pin");
  if (difference.empty()) check_factorization(scene, M0, A0, C0, factor, result);
  return result;
}

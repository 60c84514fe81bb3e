#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Sparse>

#include "check_cases.h"
#include "compare.h"
#include "fast_mass_springs_step_dense.h"
#include "fast_mass_springs_step_sparse.h"
#include "reference_functions.h"

namespace {

const char* const kReferenceFailed =
    "the reference precomputation failed on this input: a checker bug, please report it";

// Runs `steps` consecutive steps. Each step of the student's gets the reference's previous
// positions, so each step is judged alone and an early small difference cannot grow into a
// late large one.
template <typename ReferenceStep, typename StudentStep>
std::string compare_steps(const CheckScene& scene, ReferenceStep reference, StudentStep student) {
  const double tolerance = kPositionTolerance * scene_size(scene);
  Eigen::MatrixXd Uprev = scene.Uprev, Ucur = scene.Ucur;
  for (int step = 1; step <= scene.steps; ++step) {
    Eigen::MatrixXd expected, Unext;
    reference(Uprev, Ucur, expected);
    student(Uprev, Ucur, Unext);
    const std::string difference = compare_vertices(
        "Unext (step " + std::to_string(step) + " of " + std::to_string(scene.steps) + ")", Unext,
        expected, tolerance);
    if (!difference.empty()) return difference;
    Uprev = Ucur;
    Ucur = expected;
  }
  return "";
}

}  // namespace

std::string check_fast_mass_springs_step_dense(const CheckScene& scene) {
  Eigen::VectorXd r;
  Eigen::MatrixXd M, A, C;
  Eigen::LLT<Eigen::MatrixXd> factor;
  if (!reference_fast_mass_springs_precomputation_dense(scene.V, scene.E, scene.k, scene.m, scene.b,
                                                        scene.delta_t, r, M, A, C, factor))
    return kReferenceFailed;
  return compare_steps(
      scene,
      [&](const Eigen::MatrixXd& Uprev, const Eigen::MatrixXd& Ucur, Eigen::MatrixXd& Unext) {
        reference_fast_mass_springs_step_dense(scene.V, scene.E, scene.k, scene.b, scene.delta_t,
                                               scene.fext, r, M, A, C, factor, Uprev, Ucur, Unext);
      },
      [&](const Eigen::MatrixXd& Uprev, const Eigen::MatrixXd& Ucur, Eigen::MatrixXd& Unext) {
        fast_mass_springs_step_dense(scene.V, scene.E, scene.k, scene.b, scene.delta_t, scene.fext,
                                     r, M, A, C, factor, Uprev, Ucur, Unext);
      });
}

std::string check_fast_mass_springs_step_sparse(const CheckScene& scene) {
  using Sparse = Eigen::SparseMatrix<double>;
  Eigen::VectorXd r;
  Sparse M, A, C;
  Eigen::SimplicialLLT<Sparse> factor;
  if (!reference_fast_mass_springs_precomputation_sparse(
          scene.V, scene.E, scene.k, scene.m, scene.b, scene.delta_t, r, M, A, C, factor))
    return kReferenceFailed;
  return compare_steps(
      scene,
      [&](const Eigen::MatrixXd& Uprev, const Eigen::MatrixXd& Ucur, Eigen::MatrixXd& Unext) {
        reference_fast_mass_springs_step_sparse(scene.V, scene.E, scene.k, scene.b, scene.delta_t,
                                                scene.fext, r, M, A, C, factor, Uprev, Ucur, Unext);
      },
      [&](const Eigen::MatrixXd& Uprev, const Eigen::MatrixXd& Ucur, Eigen::MatrixXd& Unext) {
        fast_mass_springs_step_sparse(scene.V, scene.E, scene.k, scene.b, scene.delta_t, scene.fext,
                                      r, M, A, C, factor, Uprev, Ucur, Unext);
      });
}

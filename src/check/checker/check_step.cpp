#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Sparse>
#include <cmath>
#include <functional>
#include <limits>

#include "check_cases.h"
#include "compare.h"
#include "course_call.h"
#include "pin_weight.h"
#include "reference_functions.h"
#include "step_hints.h"

namespace {

using Sparse = Eigen::SparseMatrix<double>;
using Step = std::function<void(const Eigen::MatrixXd& fext, const Eigen::MatrixXd& Uprev,
                                const Eigen::MatrixXd& Ucur, Eigen::MatrixXd& Unext)>;

const char* const kReferenceFailed =
    "the reference precomputation failed on this input: a checker bug, please report it";

// A step of each side, set up for one scene and one pin weight w: the reference's precomputed
// r, M, A, C, a prefactorization of Q with w for each side (the student's its own object, so
// nothing it does to it reaches the reference), and the reference's step, whose y holds the
// handout's w CᵀC V, given fext + (w − 1e10) CᵀC V so that its y holds w's instead.
template <typename Matrix, typename Factor>
struct StepSides {
  bool ready = false;
  Eigen::VectorXd r;
  Matrix M, A, C;
  Factor reference_factor, student_factor;
  Eigen::MatrixXd pin_shift;  // (w − 1e10) CᵀC V, #V by 3
};

template <typename Matrix, typename Factor, typename Precomputation>
void set_up(const CheckScene& scene, double weight, Precomputation precomputation,
            StepSides<Matrix, Factor>& sides) {
  Factor handout;
  sides.ready = precomputation(scene.V, scene.E, scene.k, scene.m, scene.b, scene.delta_t, sides.r,
                               sides.M, sides.A, sides.C, handout);
  if (!sides.ready) return;
  const Matrix Q = quadratic_without_pins(scene.k, scene.delta_t, sides.M, sides.A) +
                   weight * Matrix(sides.C.transpose() * sides.C);
  sides.reference_factor.compute(Q);
  sides.student_factor.compute(Q);
  sides.pin_shift = (weight - kHandoutPinWeight) * (sides.C.transpose() * (sides.C * scene.V));
}

// Runs `steps` consecutive steps. Each step of the student's gets the reference's previous
// positions, so each step is judged alone and an early small difference cannot grow into a
// late large one. The student's Unext comes in equal to Ucur, as the course's main.cpp passes it.
void compare_steps(const CheckScene& scene, double weight, const Step& reference,
                   const Step& student, const Eigen::MatrixXd& pin_shift, CheckResult& result) {
  const double tolerance = kPositionTolerance * scene_size(scene);
  const Eigen::MatrixXd reference_fext = scene.fext + pin_shift;
  Eigen::MatrixXd Uprev = scene.Uprev, Ucur = scene.Ucur;
  for (int step = 1; step <= scene.steps; ++step) {
    Eigen::MatrixXd expected, Unext = Ucur;
    reference(reference_fext, Uprev, Ucur, expected);
    student(scene.fext, Uprev, Ucur, Unext);
    result.difference = compare_vertices(
        "Unext (step " + std::to_string(step) + " of " + std::to_string(scene.steps) + ")", Unext,
        expected, tolerance);
    if (!result.difference.empty()) {
      if (weight != kHandoutPinWeight)
        result.difference +=
            " (checked with the pin weight the step uses, w = " + pin_weight_text(weight) + ")";
      if (scene.V.rows() <= 20000)
        result.hint = step_hint(scene, weight, Uprev, Ucur, Unext, expected, tolerance);
      return;
    }
    Uprev = Ucur;
    Ucur = expected;
  }
}

template <typename Matrix, typename Factor, typename Precomputation, typename ReferenceStep,
          typename StudentStep>
CheckResult check_step(const CheckScene& scene, double weight, Precomputation precomputation,
                       ReferenceStep reference_step, StudentStep student_step) {
  CheckResult result;
  StepSides<Matrix, Factor> sides;
  set_up(scene, weight, precomputation, sides);
  if (!sides.ready) {
    result.difference = kReferenceFailed;
    return result;
  }
  const auto bind = [&](auto step, Factor& factor) -> Step {
    return [&, step](const Eigen::MatrixXd& fext, const Eigen::MatrixXd& Uprev,
                     const Eigen::MatrixXd& Ucur, Eigen::MatrixXd& Unext) {
      step(scene.V, scene.E, scene.k, scene.b, scene.delta_t, fext, sides.r, sides.M, sides.A,
           sides.C, factor, Uprev, Ucur, Unext);
    };
  };
  compare_steps(scene, weight, bind(reference_step, sides.reference_factor),
                bind(student_step, sides.student_factor), sides.pin_shift, result);
  return result;
}

// The probe scene of step_pin_weight (pin_weight.h): vertex 2 in no spring, pinned away from
// the origin; everything at rest and no force, so any consistent weight leaves it where it is.
CheckScene pin_probe_scene() {
  CheckScene scene;
  scene.V.resize(3, 3);
  scene.V << 0.25, 1.5, -0.5, 0.75, 2.0, -0.5, 1.25, 1.5, -0.5;
  scene.E.resize(1, 2);
  scene.E << 0, 1;
  scene.k = 80;
  scene.m = Eigen::Vector3d(1.0, 0.5, 2.0);
  scene.b = Eigen::VectorXi::Constant(1, 2);
  scene.delta_t = 0.01;
  scene.fext = Eigen::MatrixXd::Zero(3, 3);
  scene.Uprev = scene.Ucur = scene.V;
  return scene;
}

template <typename Matrix, typename Factor, typename Precomputation, typename StudentStep>
double probe_pin_weight(Precomputation precomputation, StudentStep student_step) {
  const CheckScene scene = pin_probe_scene();
  StepSides<Matrix, Factor> sides;
  set_up(scene, kHandoutPinWeight, precomputation, sides);
  if (!sides.ready) return std::numeric_limits<double>::quiet_NaN();
  Eigen::MatrixXd Unext = scene.Ucur;
  student_step(scene.V, scene.E, scene.k, scene.b, scene.delta_t, scene.fext, sides.r, sides.M,
               sides.A, sides.C, sides.student_factor, scene.Uprev, scene.Ucur, Unext);
  if (Unext.rows() != 3 || Unext.cols() != 3) return std::numeric_limits<double>::quiet_NaN();
  return step_pin_weight(scene.V.row(2), Unext.row(2), scene.m(2), scene.delta_t,
                         kHandoutPinWeight);
}

// Whether the step reads Unext before writing it (check_cases.h). A step that only writes Unext
// gives the same answer however Unext comes in; one that reads it first crashes, loops over
// nothing or carries the NaN through.
template <typename Matrix, typename Factor, typename Precomputation, typename StudentStep>
std::string probe_reads_unext(Precomputation precomputation, StudentStep student_step, bool empty) {
  const CheckScene scene = generated_scenes()[3];  // the seed's example E = [0 1; 1 2; 2 3]
  StepSides<Matrix, Factor> sides;
  set_up(scene, kHandoutPinWeight, precomputation, sides);
  if (!sides.ready) return "";
  const auto run = [&](Eigen::MatrixXd Unext) {
    student_step(scene.V, scene.E, scene.k, scene.b, scene.delta_t, scene.fext, sides.r, sides.M,
                 sides.A, sides.C, sides.student_factor, scene.Uprev, scene.Ucur, Unext);
    return Unext;
  };
  const Eigen::MatrixXd as_course = run(scene.Ucur);
  const double tolerance = kPositionTolerance * scene_size(scene);
  const Eigen::MatrixXd other =
      run(empty ? Eigen::MatrixXd()
                : Eigen::MatrixXd::Constant(scene.V.rows(), 3,
                                            std::numeric_limits<double>::quiet_NaN()));
  const bool same = other.rows() == as_course.rows() && other.cols() == as_course.cols() &&
                    compare_vertices("Unext", other, as_course, tolerance).empty();
  return same ? "" : kReadsUnextNote;
}

}  // namespace

CheckResult check_fast_mass_springs_step_dense(const CheckScene& scene,
                                               const CheckContext& context) {
  return check_step<Eigen::MatrixXd, Eigen::LLT<Eigen::MatrixXd>>(
      scene, context.step_pin_weight, reference_fast_mass_springs_precomputation_dense,
      reference_fast_mass_springs_step_dense, course_call_fast_mass_springs_step_dense);
}

CheckResult check_fast_mass_springs_step_sparse(const CheckScene& scene,
                                                const CheckContext& context) {
  return check_step<Sparse, Eigen::SimplicialLLT<Sparse>>(
      scene, context.step_pin_weight, reference_fast_mass_springs_precomputation_sparse,
      reference_fast_mass_springs_step_sparse, course_call_fast_mass_springs_step_sparse);
}

double probe_step_dense_pin_weight() {
  return probe_pin_weight<Eigen::MatrixXd, Eigen::LLT<Eigen::MatrixXd>>(
      reference_fast_mass_springs_precomputation_dense, course_call_fast_mass_springs_step_dense);
}

double probe_step_sparse_pin_weight() {
  return probe_pin_weight<Sparse, Eigen::SimplicialLLT<Sparse>>(
      reference_fast_mass_springs_precomputation_sparse, course_call_fast_mass_springs_step_sparse);
}

std::string probe_step_dense_reads_unext(bool empty) {
  return probe_reads_unext<Eigen::MatrixXd, Eigen::LLT<Eigen::MatrixXd>>(
      reference_fast_mass_springs_precomputation_dense, course_call_fast_mass_springs_step_dense,
      empty);
}

std::string probe_step_sparse_reads_unext(bool empty) {
  return probe_reads_unext<Sparse, Eigen::SimplicialLLT<Sparse>>(
      reference_fast_mass_springs_precomputation_sparse, course_call_fast_mass_springs_step_sparse,
      empty);
}

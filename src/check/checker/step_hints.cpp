#include "step_hints.h"

#include <Eigen/Sparse>
#include <functional>
#include <vector>

namespace {

using Sparse = Eigen::SparseMatrix<double>;

// The ways a step is run here: the handout's, and the mistakes step_hint() looks for.
struct Variant {
  bool pins_to_Ucur = false;
  double spring_sign = 1.0;  // −1: d_e of the opposite orientation
  bool unit_springs = false;
  bool without_force = false;
  bool inertia_not_divided = false;
};

// The handout's local-global iteration on one scene, built from the scene alone so a hint
// depends on no function under test.
class Iteration {
 public:
  Iteration(const CheckScene& scene, double pin_weight) : scene_(scene), pin_weight_(pin_weight) {
    const Eigen::Index n = scene.V.rows(), springs = scene.E.rows(), pins = scene.b.size();
    std::vector<Eigen::Triplet<double>> entries;
    for (Eigen::Index e = 0; e < springs; ++e) {
      entries.emplace_back(e, scene.E(e, 0), 1.0);
      entries.emplace_back(e, scene.E(e, 1), -1.0);
    }
    A_.resize(springs, n);
    A_.setFromTriplets(entries.begin(), entries.end());
    entries.clear();
    for (Eigen::Index c = 0; c < pins; ++c)
      entries.emplace_back(c, scene.b(c), 1.0);
    Sparse C(pins, n);
    C.setFromTriplets(entries.begin(), entries.end());
    CtC_ = C.transpose() * C;
    masses_over_dt2_ = scene.m / (scene.delta_t * scene.delta_t);
    const Sparse Q = scene.k * Sparse(A_.transpose() * A_) + Sparse(masses_over_dt2_.asDiagonal()) +
                     pin_weight * CtC_;
    factor_.compute(Q);
    rest_.resize(springs);
    for (Eigen::Index e = 0; e < springs; ++e)
      rest_(e) = (scene.V.row(scene.E(e, 0)) - scene.V.row(scene.E(e, 1))).norm();
  }

  bool ready() const { return factor_.info() == Eigen::Success; }

  // Runs `iterations` iterations of `variant` from Ucur, calling `after(i, p)` after each; stops
  // early when it returns true.
  void run(const Variant& variant, const Eigen::MatrixXd& Uprev, const Eigen::MatrixXd& Ucur,
           int iterations, const std::function<bool(int, const Eigen::MatrixXd&)>& after) const {
    Eigen::MatrixXd inertia = masses_over_dt2_.asDiagonal() * (2.0 * Ucur - Uprev);
    if (variant.inertia_not_divided) inertia *= scene_.delta_t * scene_.delta_t;
    const Eigen::MatrixXd y = inertia + (variant.without_force ? 0.0 : 1.0) * scene_.fext +
                              pin_weight_ * (CtC_ * (variant.pins_to_Ucur ? Ucur : scene_.V));
    Eigen::MatrixXd p = Ucur, d(scene_.E.rows(), 3);
    for (int iteration = 1; iteration <= iterations; ++iteration) {
      for (Eigen::Index e = 0; e < scene_.E.rows(); ++e) {
        const Eigen::RowVector3d unit =
            (p.row(scene_.E(e, 0)) - p.row(scene_.E(e, 1))).normalized();
        d.row(e) = variant.spring_sign * (variant.unit_springs ? 1.0 : rest_(e)) * unit;
      }
      p = factor_.solve(scene_.k * (A_.transpose() * d) + y);
      if (after(iteration, p)) return;
    }
  }

 private:
  const CheckScene& scene_;
  double pin_weight_;
  Sparse A_, CtC_;
  Eigen::VectorXd masses_over_dt2_, rest_;
  Eigen::SimplicialLLT<Sparse> factor_;
};

bool matches(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double tolerance) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) return false;
  const double worst = (a - b).rowwise().norm().maxCoeff();
  return worst <= tolerance;  // false for NaN
}

}  // namespace

std::string step_hint(const CheckScene& scene, double pin_weight, const Eigen::MatrixXd& Uprev,
                      const Eigen::MatrixXd& Ucur, const Eigen::MatrixXd& got,
                      const Eigen::MatrixXd& expected, double tolerance) {
  if (got.rows() != scene.V.rows() || got.cols() != 3 || !got.allFinite()) return "";
  const Iteration iteration(scene, pin_weight);
  if (!iteration.ready()) return "";

  // The handout's step, and another count of its iterations.
  bool fiftieth_agrees = false;
  int matched = matches(Ucur, got, tolerance) ? 0 : -1;
  iteration.run(Variant{}, Uprev, Ucur, kMostIterationsTried,
                [&](int count, const Eigen::MatrixXd& p) {
                  if (count == kAssignmentIterations)
                    fiftieth_agrees = matches(p, expected, tolerance);
                  if (matched < 0 && matches(p, got, tolerance)) matched = count;
                  return matched >= 0 && count >= kAssignmentIterations;
                });
  if (!fiftieth_agrees) return "";
  if (matched == 0) return "it returns Ucur unchanged, as after 0 local-global iterations";
  // One too many or too few is almost always the loop's first or last value (<= for <, a start
  // at 1 or at -1), so the hint points there.
  if (matched == kAssignmentIterations - 1 || matched == kAssignmentIterations + 1) {
    const std::string fixed = std::to_string(kAssignmentIterations);
    return "it matches " + std::to_string(matched) + " local-global iterations from Ucur, one " +
           (matched < kAssignmentIterations ? "fewer" : "more") + " than the assignment's " +
           fixed + ": look at the loop's bounds (for (int i = 0; i < " + fixed + "; ++i) runs " +
           fixed + " times)";
  }
  if (matched > 0 && matched != kAssignmentIterations)
    return "it matches " + std::to_string(matched) + " local-global iteration" +
           (matched == 1 ? "" : "s") + " from Ucur" +
           (matched < kAssignmentIterations ? " (does it stop early?)" : "") +
           "; the assignment's step runs a fixed " + std::to_string(kAssignmentIterations);

  struct Mistake {
    Variant variant;
    const char* hint;
  };
  Mistake mistakes[5];
  mistakes[0].variant.pins_to_Ucur = true;
  mistakes[0].hint =
      "it matches pins pulled towards Ucur, which lets them drift: y's pin term is w CᵀC V, "
      "towards the rest positions";
  mistakes[1].variant.spring_sign = -1.0;
  mistakes[1].hint =
      "it matches d_e = r_e (p_j − p_i)/‖p_i − p_j‖, the orientation opposite to A's rows (+1 at "
      "E(e,0)): for E(e,:) = [i j] use p_i − p_j";
  mistakes[2].variant.unit_springs = true;
  mistakes[2].hint = "it matches spring vectors d of length 1: d_e is r_e times the unit vector";
  mistakes[3].variant.without_force = true;
  mistakes[3].hint = "it matches a step without fext in y";
  mistakes[4].variant.inertia_not_divided = true;
  mistakes[4].hint = "it matches y with M (2 Ucur − Uprev) not divided by Δt²";
  for (const Mistake& mistake : mistakes) {
    bool found = false;
    iteration.run(mistake.variant, Uprev, Ucur, kAssignmentIterations,
                  [&](int count, const Eigen::MatrixXd& p) {
                    found = count == kAssignmentIterations && matches(p, got, tolerance);
                    return false;
                  });
    if (found) return mistake.hint;
  }
  return "";
}

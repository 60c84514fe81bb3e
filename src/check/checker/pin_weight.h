#ifndef WOBBLE_CHECK_PIN_WEIGHT_H
#define WOBBLE_CHECK_PIN_WEIGHT_H

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Sparse>
#include <string>

// The pin weight w a student's code uses, found rather than imposed. The handout asks for "some
// large value (e.g., w = 1e10)"; any weight used consistently by a precomputation and its step
// holds the pins, so each function is checked against the reference run with the weight it
// uses, and the script compares the two weights of each pair.

// The handout's weight, the reference's (src/sim/seed).
constexpr double kHandoutPinWeight = 1e10;
// The weights accepted: large enough to hold a pin to a micrometre against the course scenes'
// forces, small enough that Q stays well conditioned in double precision.
constexpr double kLightestPinWeight = 1e6;
constexpr double kHeaviestPinWeight = 1e12;

bool acceptable_pin_weight(double w);

// A weight as a FAIL or note line prints it: "1e10", "5e9", "2.5e7".
std::string pin_weight_text(double w);

// What a factorization says of its pins. A prefactorization of Q = Q0 + w CᵀC, with Q0 = k AᵀA
// + M/Δt² the reference's, satisfies for any x:  x − Q⁻¹Q0 x = w Q⁻¹CᵀC x, so two solves give w
// by least squares, and how well the two sides agree says whether the factorization has that
// form at all (a Q that is wrong elsewhere gives a poor fit, and its weight is not used).
struct FactoredPinWeight {
  double w = 0;       // the least-squares weight (0 for a Q with no pin term)
  bool fits = false;  // Q − Q0 acts on x as w CᵀC does, to 1e-6
};
//   Q0  #V by #V, C  #b by #V (at least one pin)
FactoredPinWeight factored_pin_weight(const Eigen::LLT<Eigen::MatrixXd>& factor,
                                      const Eigen::MatrixXd& Q0, const Eigen::MatrixXd& C);
FactoredPinWeight factored_pin_weight(
    const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>& factor,
    const Eigen::SparseMatrix<double>& Q0, const Eigen::SparseMatrix<double>& C);

// Q0 = k AᵀA + M/Δt²: the part of Q that is not the pins.
Eigen::MatrixXd quadratic_without_pins(double k, double delta_t, const Eigen::MatrixXd& M,
                                       const Eigen::MatrixXd& A);
Eigen::SparseMatrix<double> quadratic_without_pins(double k, double delta_t,
                                                   const Eigen::SparseMatrix<double>& M,
                                                   const Eigen::SparseMatrix<double>& A);

// The pin weight of a step, from a probe: a vertex in no spring, pinned at p₀ ≠ 0, at rest with
// no force, stepped with a prefactorization of weight w_f. Its row of Q p = b decouples:
//   (m/Δt² + w_f) p = (m/Δt²) p₀ + w_s p₀   ⇒   w_s = (p·p₀ / p₀·p₀)(m/Δt² + w_f) − m/Δt²
// exactly, whatever the iterations do elsewhere. `stepped` is where the step left it. NaN when
// it moved off the line through p₀ (the step does something else with pins).
double step_pin_weight(const Eigen::RowVector3d& rest, const Eigen::RowVector3d& stepped,
                       double mass, double delta_t, double factored_weight);

#endif

#ifndef WOBBLE_CHECK_CHECK_CASES_H
#define WOBBLE_CHECK_CHECK_CASES_H

#include <string>
#include <vector>

#include "check_scene.h"

// One check per assignment function: call the student's function (linked under the seed's name)
// and the reference (reference_functions.h) on one scene, each with the reference's inputs, and
// compare. Each returns "" when they agree, else what differs (see compare.h). They run inside
// a child process (child_process.h), so a crash, a hang or a huge allocation in the student's
// code is caught there.
std::string check_signed_incidence_matrix_dense(const CheckScene& scene);
std::string check_signed_incidence_matrix_sparse(const CheckScene& scene);
std::string check_fast_mass_springs_precomputation_dense(const CheckScene& scene);
std::string check_fast_mass_springs_precomputation_sparse(const CheckScene& scene);
std::string check_fast_mass_springs_step_dense(const CheckScene& scene);
std::string check_fast_mass_springs_step_sparse(const CheckScene& scene);

struct CheckedFunction {
  const char* name;                         // the seed's name of the function
  std::string (*check)(const CheckScene&);  // its check
  bool sparse;                              // gets the scale check too
};

// The six functions, in the assignment's order.
const std::vector<CheckedFunction>& checked_functions();

// Tolerances, relative to scene_size() for positions and lengths:
//
// Rest lengths r: the norm of the same difference of two rows of V; any correct code differs
// from the reference only in the order of three additions, far below 1e-12.
constexpr double kLengthTolerance = 1e-12;
// Masses in M: copied, not computed; 1e-12 of the largest mass allows a product with 1.0.
constexpr double kMassTolerance = 1e-12;
// A and C hold 0, +1 and -1, which any correct code produces exactly: tolerance 0.
//
// Positions from a solve with the prefactorization, and Unext: both sides solve the same system
// in double precision, differing at most in the order of sums. Q's condition number is at most
// about w / (m/Δt²) ≈ 1e10 / 1e4 = 1e6 in these scenes, so such a difference could move a
// solution by up to about 1e-10 of its size, and a step's 50 solves are each a contraction, so
// they do not add up. Measured: Wobble's dense and sparse forms agree to 5e-14 of the scene
// size on every scene, while one iteration more or fewer moves the stiff chain by 1.3e-5 of it.
constexpr double kPositionTolerance = 1e-8;

// The pin weight of the assignment, to rebuild Q for the solve check.
constexpr double kPinWeight = 1e10;

#endif

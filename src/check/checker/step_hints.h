#ifndef WOBBLE_CHECK_STEP_HINTS_H
#define WOBBLE_CHECK_STEP_HINTS_H

#include <Eigen/Core>
#include <string>

#include "check_scene.h"

// Why a step's Unext may differ from the reference's. The checker runs its own local-global
// iteration (the handout's local and global steps, sparse, with the pin weight the step uses)
// as the step should, and in the ways students' steps are found to go wrong, and compares each
// with the student's Unext:
//   - another number of iterations from Ucur, 0 to kMostIterationsTried;
//   - pins pulled towards Ucur instead of their rest positions V (y's w CᵀC Ucur);
//   - spring vectors of the opposite orientation, d_e = r_e (p_j − p_i)/‖p_i − p_j‖;
//   - spring vectors of length 1 instead of r_e;
//   - y without fext, or with M (2Ucur − Uprev) not divided by Δt².
//
//   scene       the problem (V, E, k, m, b, delta_t, fext)
//   pin_weight  w of Q and of y's pin term
//   Uprev, Ucur #V by 3 positions the step was given
//   got         #V by 3 Unext the student's step returned
//   expected    #V by 3 Unext of the reference's step (its 50 iterations): hints are given only
//               when the checker's own 50th iterate matches it, so they never guess
//   tolerance   metres, as the step check's
//
// Returns "" when nothing matches, else the hint, e.g. "it matches 51 local-global iterations
// from Ucur, one more than the assignment's 50: look at the loop's bounds (...)", or for a count
// further off "it matches 60 local-global iterations from Ucur; the assignment's step runs a
// fixed 50".
constexpr int kAssignmentIterations = 50;
constexpr int kMostIterationsTried = 200;
std::string step_hint(const CheckScene& scene, double pin_weight, const Eigen::MatrixXd& Uprev,
                      const Eigen::MatrixXd& Ucur, const Eigen::MatrixXd& got,
                      const Eigen::MatrixXd& expected, double tolerance);

#endif

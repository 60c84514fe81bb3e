#ifndef WOBBLE_CHECK_CHECK_CASES_H
#define WOBBLE_CHECK_CHECK_CASES_H

#include <limits>
#include <string>
#include <vector>

#include "check_scene.h"
#include "pin_weight.h"

// One check per assignment function: call the student's function as the course calls it
// (course_call.h) and the reference (reference_functions.h) on one scene, each with the
// reference's inputs, and compare. They run inside a child process (child_process.h), so a
// crash, a hang or a huge allocation in the student's code is caught there.

// What one check found.
struct CheckResult {
  std::string difference;          // "" when the function agrees, else what differs (compare.h)
  std::string hint;                // why it may differ, where that can be told (step_hints.h)
  std::vector<std::string> notes;  // said beside the verdict, pass or fail
  // The pin weight the function was found to use (pin_weight.h), NaN where it has none to find.
  double pin_weight = std::numeric_limits<double>::quiet_NaN();
};

// What a check knows beyond its scene.
struct CheckContext {
  // The pin weight the step was found to use (its probe), or the handout's when it could not be
  // found or is not acceptable.
  double step_pin_weight = kHandoutPinWeight;
};

CheckResult check_signed_incidence_matrix_dense(const CheckScene& scene, const CheckContext&);
CheckResult check_signed_incidence_matrix_sparse(const CheckScene& scene, const CheckContext&);
CheckResult check_fast_mass_springs_precomputation_dense(const CheckScene& scene,
                                                         const CheckContext&);
CheckResult check_fast_mass_springs_precomputation_sparse(const CheckScene& scene,
                                                          const CheckContext&);
CheckResult check_fast_mass_springs_step_dense(const CheckScene& scene, const CheckContext&);
CheckResult check_fast_mass_springs_step_sparse(const CheckScene& scene, const CheckContext&);

// The probes of a step, each run once in a child of its own before the scenes:
// the pin weight it uses (step_pin_weight in pin_weight.h; NaN when it cannot be found), and
// and whether it reads Unext before writing it: the seed's example stepped with Unext equal to
// Ucur, as the course passes it, then again with Unext empty (`empty`) or full of NaN; "" when
// both give the same, else the note to print. A crash of the empty run is an answer too, when
// the NaN run went through.
inline constexpr char kReadsUnextNote[] =
    "reads Unext before writing it: the course's main.cpp passes Unext equal to Ucur, so this "
    "works there, but Unext is an output; start from Ucur";
double probe_step_dense_pin_weight();
double probe_step_sparse_pin_weight();
std::string probe_step_dense_reads_unext(bool empty);
std::string probe_step_sparse_reads_unext(bool empty);

struct CheckedFunction {
  const char* name;                                              // the seed's name
  CheckResult (*check)(const CheckScene&, const CheckContext&);  // its check
  // The sparse functions' scale check: a chain of this many vertices (0: none). A dense #V by
  // #V or #E by #V matrix of it (7.2 GB) does not fit in the default 2 GiB, which is what the
  // check is for (the handout forbids .sparseView() on a dense matrix); work that grows with
  // the square of the vertices, slow but correct, still ends in about a second there.
  int large_vertices;
  double (*probe_pin_weight)();                  // steps only, else null
  std::string (*probe_reads_unext)(bool empty);  // steps only, else null
};

constexpr int kLargeChainVertices = 30000;

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

#endif

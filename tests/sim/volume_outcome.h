#ifndef WOBBLE_TESTS_SIM_VOLUME_OUTCOME_H
#define WOBBLE_TESTS_SIM_VOLUME_OUTCOME_H

// How far a jelly is from its rest shape at the end of an inversion test, and the check the
// volume term's tests make of it, through the API (volume_term_test.cpp) and the command line
// (tests/app/volume_inversion_cli_test.cpp).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdio>
#include <string>

#include "sim/instruments/rigid_fit.h"
#include "sim/spring_network.h"

namespace wobble::testing {

struct VolumeOutcome {
  double shape_error = 1.0;  // RMS from the best rigid placement of the rest shape / diagonal
  long inverted = -1;        // tetrahedra whose signed volume lost its rest sign
};

// Signed volume (times 6) of tetrahedron t at positions p.
inline double signed_volume(const Eigen::MatrixXi& T, const Eigen::MatrixXd& p, Eigen::Index t) {
  Eigen::Matrix3d D;
  for (int c = 0; c < 3; ++c)
    D.col(c) = (p.row(T(t, c + 1)) - p.row(T(t, 0))).transpose();
  return D.determinant();
}

// The outcome of positions `p` of the network whose rest state is `rest`.
inline VolumeOutcome volume_outcome(const SpringNetwork& rest, const Eigen::MatrixXd& p) {
  VolumeOutcome outcome;
  outcome.shape_error = rigid_fit_rms(rest.V, p) / bounding_diagonal(rest.V);
  outcome.inverted = 0;
  for (Eigen::Index t = 0; t < rest.T.rows(); ++t) {
    if (!(signed_volume(rest.T, p, t) * signed_volume(rest.T, rest.V, t) > 0.0)) ++outcome.inverted;
  }
  return outcome;
}

// With the term the jelly is back within 3% RMS of its shape and none of its tetrahedra is
// inverted; without it, it is not.
inline void expect_comes_back(const char* name, const std::string& solver,
                              const VolumeOutcome& with, const VolumeOutcome& without) {
  std::printf("[%s] %s: with the term %.4f (%ld inverted), without %.4f (%ld inverted)\n",
              solver.c_str(), name, with.shape_error, with.inverted, without.shape_error,
              without.inverted);
  EXPECT_LE(with.shape_error, 0.03) << name;
  EXPECT_EQ(with.inverted, 0) << name;
  // Without the term the network keeps the inside-out shape as a rest state.
  EXPECT_TRUE(without.shape_error > 0.03 || without.inverted > 0) << name;
}

}  // namespace wobble::testing

#endif

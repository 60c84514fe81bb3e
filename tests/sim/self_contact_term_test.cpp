// Self-contact's sweep within the iterations (SelfContactTerm::limit_iterate): a pair that opens
// with slack and is closed a little at each iteration must be pushed apart once it is short of
// its gap, although the sweep passes over open pairs whose vertices have not travelled far enough.
#include "sim/contact/self_contact_term.h"

#include <gtest/gtest.h>

#include <vector>

namespace {

using wobble::SelfCollisionParams;
using wobble::SelfContactTerm;
using wobble::SpringNetwork;
using wobble::StepContext;

// The height of point q above the plane through triangle (a, b, c), its normal up.
double height_above(const Eigen::MatrixXd& p, int q, int a, int b, int c) {
  const Eigen::Vector3d pa = p.row(a).transpose(), pb = p.row(b).transpose(),
                        pc = p.row(c).transpose();
  Eigen::Vector3d normal = (pb - pa).cross(pc - pa).normalized();
  if (normal.y() < 0.0) normal = -normal;
  return (p.row(q).transpose() - pa).dot(normal);
}

TEST(SelfContactTerm, AnOpenPairClosedIterationByIterationIsPushedApartOnceShort) {
  const double thickness = 0.01, dt = 0.01;
  // A large triangle on y = 0 and a small one parallel to it, far above in the rest shape (so
  // that the two are no rest neighbours), 15 mm above at the step's start: its three vertices make
  // open pairs with the large triangle (1.5 thicknesses: within the 2 the pairs are listed at).
  SpringNetwork rest;
  rest.V.resize(6, 3);
  rest.V << -1, 0, -1,  //
      2, 0, -1,         //
      -1, 0, 2,         //
      0.2, 1, 0.2,      //
      0.25, 1, 0.2,     //
      0.2, 1, 0.25;
  rest.F.resize(2, 3);
  rest.F << 0, 2, 1,  //
      3, 5, 4;
  rest.m = Eigen::VectorXd::Ones(6);
  SelfContactTerm term(rest);
  term.set(SelfCollisionParams{true, thickness});
  ASSERT_EQ(term.thickness_kept(thickness), thickness);
  const Eigen::VectorXd inertia = rest.m / (dt * dt);

  Eigen::MatrixXd start = rest.V;
  start.col(1).tail(3).setConstant(0.015);
  const std::vector<char> pinned(6, 0);
  StepContext step{rest, start, start, pinned, dt, 0.0};
  step.base_diagonal = &inertia;
  step.inertia = &inertia;
  term.begin_step(step, start);

  // Each iteration the solve brings the small triangle 1 mm lower; the sweep must hold it at
  // the thickness from the iteration where it would first come closer (the sixth).
  Eigen::MatrixXd p = start;
  double lowest = 1.0;
  for (int iteration = 0; iteration < 12; ++iteration) {
    p.col(1).tail(3).array() -= 0.001;
    term.limit_iterate(step, p);
    for (int q = 3; q < 6; ++q) {
      const double height = height_above(p, q, 0, 2, 1);
      lowest = std::min(lowest, height);
      EXPECT_GE(height, thickness - 1e-6) << "iteration " << iteration << ", vertex " << q;
    }
  }
  // It did come down to the thickness (so the pairs were pushed, not left open by the bounds).
  EXPECT_LT(lowest, thickness + 1e-6);
}

}  // namespace

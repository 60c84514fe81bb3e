#include "fast_mass_springs_step_dense.h"

void fast_mass_springs_step_dense(const Eigen::MatrixXd& V, const Eigen::MatrixXi& E,
                                  const double k, const Eigen::VectorXi& /*b*/,
                                  const double delta_t, const Eigen::MatrixXd& fext,
                                  const Eigen::VectorXd& r, const Eigen::MatrixXd& M,
                                  const Eigen::MatrixXd& A, const Eigen::MatrixXd& C,
                                  const Eigen::LLT<Eigen::MatrixXd>& prefactorization,
                                  const Eigen::MatrixXd& Uprev, const Eigen::MatrixXd& Ucur,
                                  Eigen::MatrixXd& Unext) {
  const double w = 1e10;
  // Everything in the right-hand side except the springs is fixed for the whole step.
  const Eigen::MatrixXd y =
      M * (2.0 * Ucur - Uprev) / (delta_t * delta_t) + fext + w * C.transpose() * C * V;

  Unext = Ucur;
  Eigen::MatrixXd d(E.rows(), 3);
  for (int iteration = 0; iteration < 50; ++iteration) {
    // Local step: the closest spring vector of rest length to the current one. normalized()
    // returns a zero vector for a zero-length spring, so coincident vertices give d = 0.
    for (Eigen::Index e = 0; e < E.rows(); ++e) {
      d.row(e) = r(e) * (Unext.row(E(e, 0)) - Unext.row(E(e, 1))).normalized();
    }
    // Global step: one prefactored solve for all three coordinates.
    Unext = prefactorization.solve(k * A.transpose() * d + y);
  }
}

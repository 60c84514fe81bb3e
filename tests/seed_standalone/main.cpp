// A stranger's program: it includes the six assignment functions by their bare header names and
// is compiled with Eigen and nothing else from Wobble (see tests/CMakeLists.txt). It drives them
// the way the assignment's main loop does and exits non-zero if dense and sparse disagree or the
// pinned end drifts, so the build proves they stand alone and the run proves they still work.
#include <Eigen/Core>
#include <cstdio>

#include "fast_mass_springs_precomputation_dense.h"
#include "fast_mass_springs_precomputation_sparse.h"
#include "fast_mass_springs_step_dense.h"
#include "fast_mass_springs_step_sparse.h"
#include "signed_incidence_matrix_dense.h"
#include "signed_incidence_matrix_sparse.h"

int main() {
  // A rope of 8 links along x, its first vertex pinned, under a force of 9.8 N down y per vertex.
  const int links = 8;
  Eigen::MatrixXd V = Eigen::MatrixXd::Zero(links + 1, 3);
  Eigen::MatrixXi E(links, 2);
  for (int i = 0; i <= links; ++i)
    V(i, 0) = 0.25 * i;
  for (int e = 0; e < links; ++e)
    E.row(e) << e, e + 1;
  const Eigen::VectorXd m = Eigen::VectorXd::Ones(links + 1);
  const Eigen::VectorXi b = Eigen::VectorXi::Zero(1);
  const double k = 100.0, delta_t = 1.0 / 30.0;
  const Eigen::MatrixXd fext = Eigen::RowVector3d(0, -9.8, 0).replicate(links + 1, 1);

  Eigen::VectorXd r_dense, r_sparse;
  Eigen::MatrixXd M_dense, A_dense, C_dense;
  Eigen::SparseMatrix<double> M_sparse, A_sparse, C_sparse;
  Eigen::LLT<Eigen::MatrixXd> llt_dense;
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> llt_sparse;
  if (!fast_mass_springs_precomputation_dense(V, E, k, m, b, delta_t, r_dense, M_dense, A_dense,
                                              C_dense, llt_dense) ||
      !fast_mass_springs_precomputation_sparse(V, E, k, m, b, delta_t, r_sparse, M_sparse, A_sparse,
                                               C_sparse, llt_sparse)) {
    std::puts("precomputation failed");
    return 1;
  }
  Eigen::MatrixXd A_check;
  signed_incidence_matrix_dense(links + 1, E, A_check);
  Eigen::SparseMatrix<double> A_sparse_check;
  signed_incidence_matrix_sparse(links + 1, E, A_sparse_check);
  if (A_check != A_dense || Eigen::MatrixXd(A_sparse_check) != A_dense) {
    std::puts("incidence matrices disagree");
    return 1;
  }

  Eigen::MatrixXd Uprev_d = V, Ucur_d = V, Unext_d, Uprev_s = V, Ucur_s = V, Unext_s;
  for (int frame = 0; frame < 90; ++frame) {
    fast_mass_springs_step_dense(V, E, k, b, delta_t, fext, r_dense, M_dense, A_dense, C_dense,
                                 llt_dense, Uprev_d, Ucur_d, Unext_d);
    fast_mass_springs_step_sparse(V, E, k, b, delta_t, fext, r_sparse, M_sparse, A_sparse, C_sparse,
                                  llt_sparse, Uprev_s, Ucur_s, Unext_s);
    Uprev_d = Ucur_d;
    Ucur_d = Unext_d;
    Uprev_s = Ucur_s;
    Ucur_s = Unext_s;
  }
  const double difference = (Ucur_d - Ucur_s).cwiseAbs().maxCoeff();
  const double pin_drift = (Ucur_s.row(0) - V.row(0)).norm();
  const double lowest = Ucur_s.col(1).minCoeff();
  std::printf("dense-sparse difference %.3g m, pin drift %.3g m, lowest point y = %.3f m\n",
              difference, pin_drift, lowest);
  // The rope must have fallen (it is 2 m long and swings down from the pin) and stay attached.
  return difference <= 1e-9 && pin_drift <= 1e-6 && lowest < -1.0 ? 0 : 1;
}

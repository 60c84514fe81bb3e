#ifndef WOBBLE_SIM_LOCAL_STEP_H
#define WOBBLE_SIM_LOCAL_STEP_H

#include <Eigen/Core>
#include <vector>

#include "sim/parallel/worker_pool.h"

namespace wobble {

// The local step fused with the product k Aᵀd (A the #E by #V signed incidence matrix):
//   d_e = r_e (p_i − p_j)/‖p_i − p_j‖ for every spring e = [i j], then rhs = y + k Aᵀd,
// so neither A nor d is formed as a sparse product. A large network's springs are split across
// the threads of a WorkerPool, then each vertex gathers its springs in a fixed order, so the
// result does not depend on the number of threads. Allocates nothing after construction.
class LocalStep {
 public:
  // E  #E by 2 springs; r  #E rest lengths; V  #V by 3 rest positions (for the direction of a
  // spring whose ends meet); pool  the threads it may use.
  LocalStep(const Eigen::MatrixXi& E, const Eigen::VectorXd& r, const Eigen::MatrixXd& V,
            WorkerPool& pool = WorkerPool::shared());

  // rhs = y + k Aᵀd(p); p, y and rhs #V by 3, rhs already of that shape. If `spring_energy` is
  // given it receives Σ(‖pᵢ − pⱼ‖ − r_e)² (m²) from the same lengths, for the convergence trace.
  void apply(const Eigen::MatrixXd& p, double k, const Eigen::MatrixXd& y, Eigen::MatrixXd& rhs,
             double* spring_energy = nullptr);

  // Below this many springs apply() runs on the calling thread alone: waking a helper costs
  // more than it saves (measured: see docs/performance.md, "Threads on a busy machine").
  static constexpr long min_springs_for_threads = 2048;
  static constexpr int pieces_per_thread = 4;
  // How often each of its two loops was shared with the pool's helpers or kept on the caller.
  const SharingPayoff& spring_payoff() const { return spring_payoff_; }
  const SharingPayoff& vertex_payoff() const { return vertex_payoff_; }

 private:
  Eigen::MatrixXi E_;
  Eigen::VectorXd r_;
  Eigen::MatrixXd rest_direction_;  // #E by 3: r_e times the unit rest vector
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> d_;  // #E by 3: this iteration's k d
  Eigen::VectorXd lengths_;  // #E: ‖pᵢ − pⱼ‖, kept only when the spring energy is asked for
  // Vertex i's springs are incident_[s] for s in [incident_start_[i], incident_start_[i+1]);
  // a non-negative entry e means i is the spring's first end (+d_e), ~e its second (−d_e).
  std::vector<int> incident_start_, incident_;
  WorkerPool* pool_;
  SharingPayoff spring_payoff_, vertex_payoff_;
};

}  // namespace wobble

#endif

#ifndef WOBBLE_SIM_CONSTRAINTS_PINS_H
#define WOBBLE_SIM_CONSTRAINTS_PINS_H

#include <Eigen/Core>
#include <vector>

#include "sim/terms/step_term.h"

namespace wobble {

// Pinned vertices and their targets: the penalty (w/2)‖Cp − C p_target‖² of the step energy,
// C the #pins by #V selection matrix. It puts w CᵀC on Q's diagonal (so pinning or unpinning
// re-factorizes Q) and w CᵀC p_target into y (so moving a target costs nothing). The first term
// of the step's list (terms/step_terms.h).
class Pins : public StepTerm {
 public:
  static constexpr double weight = 1e10;  // w

  Pins() = default;
  // initial  indices of the pinned vertices, in range, sorted, without repeats;
  // rest  #V by 3 rest positions: the targets until moved (m).
  Pins(const std::vector<int>& initial, const Eigen::MatrixXd& rest);

  // Back to the initial pins, targets at `rest`. True if the set of pinned vertices changed
  // (Q must be re-factorized).
  bool reset(const Eigen::MatrixXd& rest);
  using StepTerm::reset;  // the list's reset(): nothing (the Simulation resets the pins itself)
  // Pin vertex i with its target at `at`; false (no change) if it is already pinned.
  bool pin(int i, const Eigen::RowVector3d& at);
  // Release vertex i; false (no change) if it is not pinned.
  bool unpin(int i);
  // Throws std::invalid_argument if i is not pinned or the target is not finite.
  void set_target(int i, const Eigen::Vector3d& target);
  const char* name() const override { return "pins"; }
  // diagonal (#V) += w at each pinned vertex.
  void add_diagonal(const StepContext& step, Eigen::VectorXd& diagonal) override;
  // y += w CᵀC p_target, y #V by 3.
  void add_fixed_rhs(Eigen::MatrixXd& y) const override;
  // (w/2)‖Cp − C p_target‖² (J); gradient += w CᵀC(p − p_target).
  double add_energy(const StepContext& step, const Eigen::MatrixXd& p,
                    Eigen::MatrixXd* gradient) const override;

  // Throws std::out_of_range, naming `what`, unless 0 ≤ i < #V.
  void check_vertex(int i, const char* what) const;
  const std::vector<char>& flags() const { return pinned_; }   // #V
  const Eigen::MatrixXd& targets() const { return targets_; }  // #V by 3, read at pinned rows
  int count() const { return count_; }
  // Pinned vertex indices in increasing order.
  std::vector<int> list() const;

 private:
  std::vector<int> initial_;
  std::vector<char> pinned_;
  Eigen::MatrixXd targets_;
  int count_ = 0;
};

}  // namespace wobble

#endif

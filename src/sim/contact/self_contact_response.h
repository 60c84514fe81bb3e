#ifndef WOBBLE_SIM_CONTACT_SELF_CONTACT_RESPONSE_H
#define WOBBLE_SIM_CONTACT_SELF_CONTACT_RESPONSE_H

#include <Eigen/Core>
#include <vector>

#include "sim/contact/self_contact_detection.h"

namespace wobble {

// Pushes a step's positions so that every pair keeps its gap: each pair is a linear constraint
// on four vertices, (Σ βₖxₖ)·n ≥ target, enforced by Gauss-Seidel projection weighted by
// inverse masses (a vertex with inverse mass 0 does not move). The first sweep visits every
// pair; later sweeps only the pairs of the vertices the sweep before pushed (found through a
// vertex-to-pair index), so the sweeps cost what they push, not the number of pairs times the
// number of sweeps.
// Coulomb friction (μ) then acts on the sliding of a vertex over a triangle's face.
class SelfContactResponse {
 public:
  static constexpr int max_sweeps = 128;
  // The most pair visits a separation makes, in sweeps over all its pairs (see separate()).
  static constexpr std::size_t sweep_budget = 32;
  // Sweeps stop once no pair is short of its target by more than this fraction of the thickness.
  static constexpr double settled_fraction = 1e-3;

  //   pairs         the step's pairs; their depth (m) grows by each push
  //   current       #V by 3 positions at the start of the step (m), for friction's sliding
  //   inverse_mass  #V, 1/kg
  //   friction      μ (0: none)
  //   thickness     m
  //   next          #V by 3 positions (m), moved
  void respond(std::vector<SelfContactPair>& pairs, const Eigen::MatrixXd& current,
               const Eigen::VectorXd& inverse_mass, double friction, double thickness,
               Eigen::MatrixXd& next);
  // Sweeps alone (after something else moved `next`).
  void separate(std::vector<SelfContactPair>& pairs, const Eigen::VectorXd& inverse_mass,
                double thickness, Eigen::MatrixXd& next);

  std::size_t memory_bytes() const {
    return (moved_.capacity() + moved_list_.capacity() + active_.capacity() +
            pair_start_.capacity() + pair_ids_.capacity() + fill_.capacity() +
            pair_seen_.capacity()) *
           sizeof(int);
  }

 private:
  // One sweep over the pairs that may need it; returns the largest violation found (m).
  double sweep(std::vector<SelfContactPair>& pairs, const Eigen::VectorXd& inverse_mass, int number,
               Eigen::MatrixXd& next);
  void apply_friction(std::vector<SelfContactPair>& pairs, const Eigen::MatrixXd& current,
                      const Eigen::VectorXd& inverse_mass, double friction, Eigen::MatrixXd& next);
  // The pairs of each vertex (CSR over #V), for finding the pairs a push may have disturbed.
  void index_pairs(const std::vector<SelfContactPair>& pairs, int vertex_count);
  // active_ = the pairs of the vertices the sweep before `number` pushed, in order.
  void gather_active(int number);
  // #V: the last sweep that pushed each vertex (−1: none yet); the vertices the current sweep
  // pushed.
  std::vector<int> moved_, moved_list_;
  std::vector<int> active_, pair_start_, pair_ids_, fill_, pair_seen_;
};

}  // namespace wobble

#endif

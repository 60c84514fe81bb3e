#ifndef WOBBLE_SIM_VOLUME_VOLUME_TERM_H
#define WOBBLE_SIM_VOLUME_VOLUME_TERM_H

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "sim/parallel/worker_pool.h"
#include "sim/terms/step_term.h"
#include "sim/volume/tet_rotations.h"

namespace wobble {

struct TermSetup;

// The volume term of a solid (projective dynamics' strain term, Bouaziz et al. 2014, in the
// same local-global iteration as the springs): for every tetrahedron t of volume vₜ and
// deformation gradient Fₜ(p) = Ds(p)·Dm⁻¹,
//   E(p) = (w/2) Σₜ vₜ ‖Fₜ(p) − Rₜ‖²_F,  Rₜ the proper rotation nearest Fₜ.
// Fₜ is linear in p (Fₜ = Pₜᵀ Gₜ, Pₜ the 4 by 3 corners, Gₜ 4 by 3 from the rest shape), so
// the quadratic part is a fixed matrix K = w Σₜ vₜ GₜGₜᵀ on Q (add_matrix) and the local step is
// Rₜ, whose pull w vₜ GₜRₜᵀ joins the right-hand side: the springs' local step with a rotation
// in place of a direction. Its gradient is w vₜ Gₜ(Fₜ − Rₜ)ᵀ per tetrahedron.
class VolumeTerm : public StepTerm {
 public:
  // V  #V by 3 rest positions; T  #T by 4 tetrahedra (none flat); stiffness w (Pa);
  // pool  the threads it may use for a large mesh.
  VolumeTerm(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T, double stiffness,
             WorkerPool& pool = WorkerPool::shared());

  const char* name() const override { return "volume"; }
  void add_matrix(std::vector<Eigen::Triplet<double>>& K) const override;
  TermStep begin_step(const StepContext& /*step*/, const Eigen::MatrixXd& /*first*/) override {
    return TermStep{/*in_solve=*/true};
  }
  void add_targets(const StepContext& step, const Eigen::MatrixXd& p, Eigen::MatrixXd& rhs,
                   double* energy) override;
  double add_energy(const StepContext& step, const Eigen::MatrixXd& p,
                    Eigen::MatrixXd* gradient) const override;
  void project(const StepContext& step, Eigen::MatrixXd& next) override;
  bool reset() override;
  void report(std::vector<TermFigure>& figures) const override;

  // The tetrahedra inverted (det F ≤ 0) at the end of the last step.
  long inverted() const { return inverted_; }
  // Below this many tetrahedra the local step runs on the calling thread alone.
  // (A tetrahedron's update costs about as much as a few springs' local step: the pool's
  // payoff measure decides from there whether sharing pays.)
  static constexpr long min_tets_for_threads = 1024;

 private:
  // Each tetrahedron's pull, or its gradient if `gradient`, and, if `energy`, its energy (into
  // rotations_); the rotations are turned up to `most` times from the last ones.
  void local_step(const Eigen::MatrixXd& p, int most, double tolerance, bool gradient,
                  bool energy) const;
  // out (#V by 3) += each vertex's pulls, summed in the order of its slots.
  void gather(Eigen::MatrixXd& out) const;
  Eigen::Matrix3d deformation(const Eigen::MatrixXd& p, Eigen::Index t) const;

  Eigen::MatrixXi T_;
  std::vector<Eigen::Matrix<double, 4, 3>> G_;  // #T: F = Pᵀ G
  Eigen::VectorXd weight_;                      // #T: w vₜ (N·m)
  // vertex → where its (tetrahedron, corner) pulls are in rotations_.out() (incident_) and in
  // rotations_.single_out() (incident_single_), in the order of (t, c), so each vertex sums its
  // pulls in one fixed order whatever the threads.
  std::vector<int> incident_start_, incident_, incident_single_;
  mutable TetRotations rotations_;  // the last Rₜ (warm start), the pulls, the energies
  WorkerPool* pool_;
  mutable SharingPayoff tet_payoff_, vertex_payoff_;
  long inverted_ = 0;
};

// The volume stiffness (Pa) of the shipped jellies, the setting "volume-stiffness"'s default.
constexpr double volume_default_stiffness = 2e4;

// The registered factory (sim/registered_terms.cpp): the volume term for a network with
// tetrahedra when the switch "volume" is on, at the setting "volume-stiffness" (Pa); nullptr
// when the switch is off, the stiffness 0 or there are no tetrahedra.
std::unique_ptr<StepTerm> make_volume_term(const TermSetup& setup);

}  // namespace wobble

#endif

#ifndef WOBBLE_SIM_CONTACT_SOLVE_CONTACT_H
#define WOBBLE_SIM_CONTACT_SOLVE_CONTACT_H

#include <Eigen/Core>
#include <vector>

#include "sim/contact/collider_contact.h"
#include "sim/terms/step_term.h"

namespace wobble {

// Contact with the colliders as a term of the step's energy, so that the solve sees the floor
// (projective dynamics' collision constraints). Each vertex near a collider at the start of a
// step joins the step's contact set S and gets the term
//   (κᵢ/2) ‖pᵢ − Pᵢ(p)‖²,
// Pᵢ(p) the point ColliderContact::outside_point puts it at: out of every collider to the contact
// offset, held back by Coulomb friction. κᵢ = weight_scale × (k·degᵢ + (1 + cΔt)mᵢ/Δt²), Q's own
// diagonal entry for the vertex, so that the contact is as stiff as what holds the vertex
// already. κ goes on Q's diagonal for a lagged set H ⊇ what S was when H was last chosen, so
// that a contact set that changes as a cloth slides does not refactorize Q each step:
//   - H is chosen again (as S) only when S has members outside it or H holds vertices that
//     left S, and at most once every lag_steps steps (at once only for a first contact);
//   - a member of S in H: the local step adds κᵢPᵢ(p) to the right-hand side of vertex i;
//   - a vertex of H not in S (or outside every collider): κᵢpᵢ, its target is itself, the term
//     is zero and only slows that vertex;
//   - a member of S not yet in H: its whole force κ'ᵢ(Pᵢ(p) − pᵢ) in the right-hand side, with
//     κ'ᵢ = rhs_weight_scale (1 + cΔt)mᵢ/Δt², small against the inertia on Q's diagonal so that
//     the iteration stays a contraction even for a whole layer landing at once;
//   - L-BFGS: the energy adds (κᵢ/2) Σ_c max(0, offset − φ_c(pᵢ))² and friction (see energy()),
//     κ'ᵢ in place of κᵢ outside H.
// Then the usual projection after the iterations (ColliderContact) only mops up what the last
// iterate left: typically κ's compliance, micrometres, and the few vertices not yet in H.
class SolveContact {
 public:
  // κ as a multiple of the vertex's own Q diagonal. The term slows a member's motion along the
  // surface too (the iteration's target for it is where it was), so κ is kept small: large
  // enough to hold the jelly_drop's shape as it lands, small enough that a frictionless
  // tablecloth still slides off its table (docs/performance.md, "Contact's weight and the
  // self-contact grid").
  static constexpr double weight_scale = 0.05;
  // How long H is kept while S changes (steps). With
  // Chebyshev acceleration H follows S every step: the acceleration's extrapolation needs Q to
  // describe the contact it meets (with a lagged H the drape over a sphere was driven through it).
  static constexpr int lag_steps = 10;
  // κ' outside H, as a multiple of the vertex's inertia on Q's diagonal.
  static constexpr double rhs_weight_scale = 0.5;

  // The base diagonal (k·degᵢ + (1 + cΔt)mᵢ/Δt², #V) and its inertia part ((1 + cΔt)mᵢ/Δt²)
  // after k, Δt, damping or masses changed; rescales the weights.
  void set_base_diagonal(const Eigen::VectorXd& base, const Eigen::VectorXd& inertia);
  // Chooses S for the step about to be taken from its first iterate `first` (#V by 3): a vertex
  // joins when it starts within its margin of a collider (the offset, twice its motion over the
  // step, and gravity's reach), and leaves when twice that far. Pinned vertices never join.
  // Chooses H again when due (see the class comment). Returns whether H changed, and with it κ
  // on Q's diagonal.
  bool choose(const ColliderContact& contact, const StepContext& step, const Eigen::MatrixXd& first,
              double gravity_reach);
  // Whether H lags behind S (see lag_steps); on by default.
  void set_lagging(bool on) { lagging_ = on; }
  // Empties S and H (a reset, or colliders gone); returns whether H held anything.
  bool clear();
  // κ for each vertex (#V; 0 outside H), what goes on Q's diagonal; empty while H is.
  const Eigen::VectorXd& weights() const { return weights_; }
  // Whether S is empty (nothing near a collider) and H too (nothing in the solve).
  bool empty() const { return members_.empty() && held_.empty(); }
  const std::vector<int>& members() const { return members_; }

  // Local-global: rhs_i += κᵢ Pᵢ(p) for i in S (rhs #V by 3). If `energy` is given it receives
  // the term's value Σ (κᵢ/2)‖pᵢ − Pᵢ(p)‖² (J), for the convergence trace.
  void add_targets(const ColliderContact& contact, const StepContext& step,
                   const Eigen::MatrixXd& p, Eigen::MatrixXd& rhs, double* energy = nullptr) const;
  // L-BFGS: the contact energy at p (J), and, if given, its gradient added into `gradient`
  // (#V by 3, N):
  //   Σ_{i∈S} Σ_c (κᵢ/2) max(0, offset − φ_c(pᵢ))²  +  friction,
  // friction μλᵢ f(‖uᵢ‖) on the slide uᵢ of pᵢ over the step in the tangent plane of its contact
  // at the start of the step, λᵢ the normal force it carried then (κᵢ times its depth), and f
  // Huber's: u²/(2ε) below ε (static friction as a stiff spring), u − ε/2 above (Coulomb).
  double energy(const ColliderContact& contact, const StepContext& step, const Eigen::MatrixXd& p,
                Eigen::MatrixXd* gradient) const;
  // After the solve, before the projection: the normal force κᵢ × depth each member carries at
  // the solved positions `p` (#V by 3), the next step's friction budget for L-BFGS.
  void record_forces(const ColliderContact& contact, const Eigen::MatrixXd& p);
  // The normal forces record_forces found (#V, N; 0 outside S), or empty.
  const Eigen::VectorXd& normal_forces() const { return normal_force_; }
  // #V flags from record_forces: the members within 1% of the offset of a collider or inside it
  // (empty before the first).
  const std::vector<char>& touching() const { return touching_; }
  // L-BFGS: fixes each member's contact normal (at pᵗ) and friction force μλᵢ for the step (call
  // after choose()).
  void lag_friction(const ColliderContact& contact, const StepContext& step);

 private:
  // κ the solve uses for member s of S: κᵢ in H, κ'ᵢ outside.
  double member_weight(int i) const;

  Eigen::VectorXd base_, inertia_;
  Eigen::VectorXd weights_;         // #V: κ on H, else 0; empty when H is
  std::vector<char> member_flags_;  // #V: in S
  std::vector<int> members_;        // S
  std::vector<char> held_flags_;    // #V: in H
  std::vector<int> held_;           // H
  std::vector<int> held_only_;      // H less S, this step
  int steps_since_chosen_ = 0;
  bool lagging_ = true;
  Eigen::VectorXd normal_force_;  // #V (N), from record_forces
  std::vector<char> touching_;    // #V, from record_forces
  // Per member, for the L-BFGS friction: the contact normal at the start and μλ (N).
  std::vector<Eigen::Vector3d> friction_normal_;
  std::vector<double> friction_force_;
  std::vector<int> friction_collider_;
};

}  // namespace wobble

#endif

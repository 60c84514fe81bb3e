#ifndef WOBBLE_SIM_CONTACT_SELF_CONTACT_TERM_H
#define WOBBLE_SIM_CONTACT_SELF_CONTACT_TERM_H

#include <Eigen/Core>
#include <cstdint>
#include <utility>
#include <vector>

#include "sim/contact/self_collision.h"
#include "sim/contact/self_contact_proximity.h"
#include "sim/contact/self_crossing_guard.h"
#include "sim/spring_network.h"
#include "sim/terms/step_term.h"
#include "sim/terms/step_terms.h"

namespace wobble {

// Self-contact as a term inside the solve: the surface (the render triangles F) kept
// `thickness` apart from its own layers during the iterations, with Coulomb friction between
// them, and no crossing by construction. Q is never touched. docs/method.md, "Self-contact".
//
// An epoch starts at positions x free of crossings (the step's pᵗ, or a bounded iterate):
// SelfContactProximity lists the vertex-triangle and edge-edge pairs within 2·thickness and
// gives each vertex a bound bᵥ on how far it may move from x, relative to a common motion,
// before anything could pass through anything else (Offset Geometric Contact's conservative
// bounds, Chen et al. 2025). Reaches follow where the step is heading: 1.5 × each vertex's
// predicted motion less the mean, at least the thickness. An epoch outlives its step while every
// vertex stays within keep_fraction of its bound (nothing is found again for a pile at rest).
//
// Each pair keeps g(p) = target − (Σ βₖpₖ)·n ≤ 0 with its normal n and closest points β from x
// (target: the thickness, or a tenth of it more than the pair had if it started closer). After
// every update of the iterate (limit_iterate):
//   1. one Gauss-Seidel sweep pushes each pair with g > 0 apart along n, its vertices weighted by
//      inverse mass (pins do not give way);
//   2. each pair's force λ ≥ 0 (N) follows: λ ← max(0, λ + κg), κ = η/Σₖ(βₖ²/Wₖ) with Wₖ the
//      vertex's inertia (1 + cΔt)mₖ/Δt² (what would have moved free masses as far); the local
//      step adds λβₖn to vertex k (add_targets), so that the global step learns the contact
//      instead of meeting it anew each iteration, and with it Coulomb friction −μλ·s/max(‖s‖, ε)
//      against the closest points' slide s over the step (ε = friction_width(): below it,
//      static friction as a stiff spring); λ carries over to the same pair next step;
//   3. every vertex beyond its bound is moved back within it, the common motion taken out; if any
//      was, a new epoch starts from the bounded iterate (at most max_epochs a step).
// L-BFGS sees the energy (κ/2) max(0, g + λ/κ)² per pair with Huber friction μλ·f(‖s‖), and the
// same limit_iterate after each accepted step.
// After the solve (project): the bounds once more (the colliders' projection may have moved a
// vertex), and the crossing guard (SelfCrossingGuard) as the last resort, reporting how many
// vertices it put back, where the bounds do not keep every pair apart (a search stopped, or found
// a pair closer than its floor: SelfContactProximity::covers_every_pair).
class SelfContactTerm : public StepTerm {
 public:
  static constexpr double gain = 0.5;  // η: κ as a share of the pair's inertia
  static constexpr int max_epochs = 3;
  // Pairs are listed within this many thicknesses.
  static constexpr double contact_reach = 2.0;
  // An epoch is kept into the next step while every vertex is within this fraction of its bound.
  static constexpr double keep_fraction = 0.5;

  // `rest`, the network (F and masses), must outlive it. μ is the step's (StepContext::friction).
  explicit SelfContactTerm(const SpringNetwork& rest);

  // On, off or a new thickness; the params must already be valid.
  void set(const SelfCollisionParams& params);
  bool on() const { return on_; }
  // The gap kept (m): the asked thickness clamped to largest_self_collision_thickness.
  double thickness_kept(double asked) const;

  const char* name() const override { return "self-contact"; }
  TermStep begin_step(const StepContext& step, const Eigen::MatrixXd& first) override;
  void add_targets(const StepContext& step, const Eigen::MatrixXd& p, Eigen::MatrixXd& rhs,
                   double* energy) override;
  double add_energy(const StepContext& step, const Eigen::MatrixXd& p,
                    Eigen::MatrixXd* gradient) const override;
  bool limit_iterate(const StepContext& step, Eigen::MatrixXd& p) override;
  void project(const StepContext& step, Eigen::MatrixXd& next) override;
  void end_step() override;
  bool reset() override;
  void report(std::vector<TermFigure>& figures) const override;

  // Vertices with a pair pressing on them after the last step, and the same as #V flags.
  int contact_count() const { return on_ ? contact_count_ : 0; }
  const std::vector<char>& contact_vertices() const;
  // Memory held (bytes), for the benchmark.
  std::size_t memory_bytes() const;

 private:
  struct Pair {
    SelfContactPair features;
    double stiffness = 0.0;  // κ (N/m)
    double force = 0.0;      // λ (N)
    double friction = 0.0;   // μλ̄ lagged for L-BFGS (N)
    std::uint64_t key = 0;
    // separate()'s: −g when last looked at (m; not above 0 means look), and the pair's
    // Σₖ|βₖ|·travel then (m).
    double slack = -1.0;
    double travel_at = 0.0;
  };
  void build_surface();
  // Finds the pairs and bounds at x_ (reaches from `heading`, #V by 3), κ and λ's start.
  void start_epoch(const StepContext& step, const Eigen::MatrixXd& heading);
  // g(p) (m) and the closest points' slide in the tangent plane from anchor_ (m): over the step,
  // or over the steps a kept epoch spans, so that a resting pile does not creep (friction's).
  double violation(const Pair& pair, const Eigen::MatrixXd& p, Eigen::Vector3d* slide) const;
  // The same with vertex v at position(v) (the sweep reads packed rows).
  template <typename Position>
  double violation(const Pair& pair, Position position, Eigen::Vector3d* slide) const;
  // Huber's width for friction (m): slides below it are held as by a stiff spring.
  double friction_width() const { return 0.01 * thickness_; }
  // Friction of `strength` (N, μλ) against a pair's slide (m): subtracts its force on the
  // closest points from `force` and returns its energy (J), both Huber's (friction_width()).
  double add_friction(double strength, const Eigen::Vector3d& slide, Eigen::Vector3d& force) const;
  // The surface's common motion from x_ to p (m): the median along each axis (see the .cpp).
  Eigen::Vector3d common_motion(const Eigen::MatrixXd& p) const;
  // Whether every surface vertex of p is within `fraction` of its bound, the common motion out.
  bool within(const Eigen::MatrixXd& p, double fraction) const;
  // The λ last step's pair with this key ended with, or 0.
  double remembered_force(std::uint64_t key) const;
  std::size_t remembered_slot(std::uint64_t key) const;
  // One sweep pushing the pairs of p apart; returns how many it pushed.
  int separate(const StepContext& step, Eigen::MatrixXd& p);

  const SpringNetwork* rest_;
  bool on_ = false;
  double thickness_ = 0.0;
  bool built_ = false;
  bool epoch_open_ = false;  // x_, the pairs and bounds describe an epoch still in force
  // Whether the epoch's search, and every search this step, kept every pair apart
  // (SelfContactProximity::covers_every_pair): the guard is then skipped.
  bool epoch_covered_ = false, step_covered_ = false;
  SelfCollisionSurface surface_;
  RestNeighbours rest_neighbours_;
  SelfContactProximity proximity_;
  SelfCrossingGuard guard_;
  Eigen::MatrixXd x_;  // #V by 3: where the epoch started
  // #V rows: where friction measures slides from: where the step's first epoch started (the
  // step's start, or steps back while that epoch is kept), not where an epoch within the step
  // started (a bounded iterate): from there friction held the iterate to where the bounds had
  // put it, and the shipped pile gained energy without end once it lay (2.8 J at the start,
  // 38 J by step 700).
  std::vector<Eigen::Vector3d> anchor_;
  std::vector<Eigen::Vector3d> rows_;  // the iterate separate() sweeps, row by row
  // separate()'s: the iterate after the last limit_iterate, and each vertex's path length since
  // the step's or epoch's first sweep (m).
  std::vector<Eigen::Vector3d> last_rows_;
  std::vector<Eigen::Vector3d> rhs_rows_;  // add_targets' packed right-hand side
  std::vector<double> travel_;
  bool sweep_fresh_ = true;
  Eigen::MatrixXd heading_;  // #V by 3: an iterate before its bounds
  Eigen::VectorXd reach_, bounds_;
  std::vector<SelfContactPair> found_;
  std::vector<Pair> pairs_;
  // Last step's (key, λ > 0) as a hash table; λ = 0 marks an empty slot (remembered_force).
  std::vector<std::pair<std::uint64_t, double>> remembered_;
  std::vector<char> in_contact_, watched_, put_back_;
  static constexpr std::size_t max_motion_samples = 1024;
  mutable std::vector<double> motion_samples_;  // common_motion's buffer
  Eigen::VectorXd inverse_mass_;
  int epochs_ = 0, clamped_ = 0, contact_count_ = 0, repaired_ = 0;
  double detection_ms_ = 0.0, solve_ms_ = 0.0, guard_ms_ = 0.0;
};

// The vertices a layer of the same surface pressed on in the last step among a step's terms
// (#V flags; empty without self-contact).
const std::vector<char>& self_contact_vertices(const StepTerms& terms);
// The gap self-contact keeps (m): `asked`, clamped to what the mesh can keep
// (largest_self_collision_thickness) where self-contact is among the terms.
double self_collision_thickness_kept(const StepTerms& terms, double asked);

}  // namespace wobble

#endif

#ifndef WOBBLE_SIM_TERMS_STEP_TERM_H
#define WOBBLE_SIM_TERMS_STEP_TERM_H

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "sim/spring_network.h"

namespace wobble {

// What a term sees of the step about to be taken (or being taken): the state, and what the
// settings and the solver say about the step, so that no term reaches into the Simulation.
struct StepContext {
  const SpringNetwork& rest;        // rest shape, springs, render triangles, masses
  const Eigen::MatrixXd& current;   // #V by 3 pᵗ (m)
  const Eigen::MatrixXd& previous;  // #V by 3 pᵗ⁻ᐞᵗ (m)
  const std::vector<char>& pinned;  // #V flags
  double dt;                        // Δt (s)
  double time;                      // simulated time at the start of the step (s)
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  // g (m/s²; N on each vertex by its model)
  double friction = 0.0;  // μ, the settings' friction between surfaces (≥ 0)
  // Whether the solver extrapolates its iterates (Chebyshev): a term's weights on Q's diagonal
  // then follow what it meets every step instead of lagging.
  bool extrapolated = false;
  // Q's diagonal without the terms, k·degᵢ + (1 + cΔt)mᵢ/Δt², and its inertia part
  // (1 + cΔt)mᵢ/Δt² (#V each, N/m); null before Q is first factorized.
  const Eigen::VectorXd* base_diagonal = nullptr;
  const Eigen::VectorXd* inertia = nullptr;
};

// What a term's begin_step says of the step it begins.
struct TermStep {
  bool in_solve = false;          // it adds something inside the iterations (else skipped there)
  bool diagonal_changed = false;  // its weights on Q's diagonal changed: Q is refactorized
  bool touching = false;          // the last step touched something (a collider, itself): the
                                  // problem may change sharply between iterations
};

// One figure a term reports about the last step, by name: ("self-contact", "detection", "ms",
// 1.2). The panel, --stats and the term CSV show every figure without code per term. The names
// are string literals (they outlive any copy).
struct TermFigure {
  const char* term;
  const char* name;
  const char* unit;  // "ms", or "" for a count
  double value;
};

// Wall-clock time of the last step, split between the local step (springs), the global step
// (the prefactored solve) and the parts around them (ms), and each term's own figures.
struct StepTiming {
  double local_ms = 0.0;
  double global_ms = 0.0;
  double forces_ms = 0.0;       // the terms' forces (wind)
  double instruments_ms = 0.0;  // the convergence trace, while it is recorded
  double total_ms = 0.0;
  std::vector<TermFigure> figures;  // in the terms' order
  // The figure `name` of term `term`, or 0 when no term reported it.
  double figure(const char* term, const char* name) const;
};

// A term of the step's energy beyond the springs and the inertia: the pins, each force, contact
// with the colliders, self-contact. The Simulation keeps them in one list (StepTerms), and every
// solver sees every term through it: the list is the problem. Each hook has a default that does
// nothing, so a term overrides only what it does.
//
// A term that acts inside the solve has the form (κ/2)‖p − T(p)‖² per vertex: κ on Q's diagonal
// (add_diagonal), κT(p) added to the local step's right-hand side (add_targets), or, for a
// term that keeps Q as it is, its whole force κ(T(p) − p) in the right-hand side. Either way
// its gradient is D p − (what it adds to the right-hand side), D what it put on Q's diagonal,
// which is what the convergence trace relies on; add_energy gives the same energy and gradient
// directly (L-BFGS). A term whose weight couples vertices (the volume term's (w/2)‖F − R‖² per
// tetrahedron) puts a fixed matrix K on Q instead (add_matrix, read once when the term is
// made); its gradient is then K p − (what it adds to the right-hand side).
class StepTerm {
 public:
  virtual ~StepTerm() = default;
  // The name its figures carry ("pins", "wind", "collider contact", "self-contact").
  virtual const char* name() const = 0;

  // Explicit forces of the step (#V by 3, N), once at its start. `fext` arrives holding gravity
  // and the forces of the terms before this one.
  virtual void add_forces(const StepContext& /*step*/, Eigen::MatrixXd& /*fext*/) {}
  // diagonal (#V) += its weights on Q's diagonal, which may follow Q's own diagonal
  // (step.base_diagonal, step.inertia). Called whenever Q is refactorized: k, Δt, damping, the
  // pins or a term's weights changed.
  virtual void add_diagonal(const StepContext& /*step*/, Eigen::VectorXd& /*diagonal*/) {}
  // K += its fixed part of Q, a symmetric #V by #V matrix (both triangles listed; repeats are
  // summed). Read once when the made terms are built; Q keeps it until they are built again.
  virtual void add_matrix(std::vector<Eigen::Triplet<double>>& /*K*/) const {}
  // y (#V by 3, N) += what it adds to the right-hand side for the whole step (pin targets).
  virtual void add_fixed_rhs(Eigen::MatrixXd& /*y*/) const {}
  // Begins a step from its first iterate `first` (#V by 3): chooses its set, and says whether it
  // acts inside the iterations, whether its weights on Q's diagonal changed and whether the last
  // step touched something.
  virtual TermStep begin_step(const StepContext& /*step*/, const Eigen::MatrixXd& /*first*/) {
    return TermStep{};
  }
  // Local-global, a term in the solve: rhs (#V by 3) += its targets for the iterate p; `energy`,
  // if given, += its energy at p (J). Not const: a term may update its own multipliers from each
  // iterate (self-contact's forces).
  virtual void add_targets(const StepContext& /*step*/, const Eigen::MatrixXd& /*p*/,
                           Eigen::MatrixXd& /*rhs*/, double* /*energy*/) {}
  // Its energy at p (J); `gradient`, if given, += its gradient (#V by 3, N).
  virtual double add_energy(const StepContext& /*step*/, const Eigen::MatrixXd& /*p*/,
                            Eigen::MatrixXd* /*gradient*/) const {
    return 0.0;
  }
  // A term in the solve, after each update of the iterate (a global solve, a line search's
  // step): may move p (#V by 3) back within what the term allows (self-contact's displacement
  // bounds). Returns whether it moved any vertex.
  virtual bool limit_iterate(const StepContext& /*step*/, Eigen::MatrixXd& /*p*/) { return false; }
  // After the last iteration: a last guard that moves the solved positions `next` (#V by 3).
  virtual void project(const StepContext& /*step*/, Eigen::MatrixXd& /*next*/) {}
  // Its figures of the last step, appended to `figures`.
  virtual void report(std::vector<TermFigure>& /*figures*/) const {}
  // The step was accepted.
  virtual void end_step() {}
  // Back to the start (Simulation::reset). Returns whether its weights on Q's diagonal changed.
  virtual bool reset() { return false; }
};

}  // namespace wobble

#endif

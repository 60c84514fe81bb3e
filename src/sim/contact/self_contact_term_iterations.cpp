#include "sim/contact/self_contact_term.h"

#include <algorithm>
#include <cmath>

#include "sim/contact/vertex_row.h"
#include "sim/instruments/stopwatch.h"

// SelfContactTerm's work within the solve's iterations: the pairs' forces in the right-hand
// side, their energy for L-BFGS, and after each iterate the sweep that pushes pairs apart and
// the bounds (the term's epochs and the step around them are in self_contact_term.cpp).

namespace wobble {

template <typename Position>
double SelfContactTerm::violation(const Pair& pair, Position position,
                                  Eigen::Vector3d* slide) const {
  const SelfContactPair& f = pair.features;
  Eigen::Vector3d q = Eigen::Vector3d::Zero(), moved = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d at = position(f.vertex[k]);
    q += f.beta[k] * at;
    if (slide) moved += f.beta[k] * (at - anchor_[f.vertex[k]]);
  }
  if (slide) *slide = moved - moved.dot(f.normal) * f.normal;
  return f.target - q.dot(f.normal);
}

double SelfContactTerm::violation(const Pair& pair, const Eigen::MatrixXd& p,
                                  Eigen::Vector3d* slide) const {
  return violation(
      pair, [&](int v) { return vertex_row(p, v); }, slide);
}

void SelfContactTerm::add_targets(const StepContext& step, const Eigen::MatrixXd& p,
                                  Eigen::MatrixXd& rhs, double* energy) {
  const Stopwatch stopwatch;
  const double mu = step.friction;
  double sum = 0.0;
  // Added to packed rows of rhs (the same additions in the same order as to rhs itself).
  bool packed = false;
  for (const Pair& pair : pairs_) {
    if (!(pair.force > 0.0)) continue;
    if (!packed) {
      pack_rows(rhs, rhs_rows_);
      packed = true;
    }
    Eigen::Vector3d force = pair.force * pair.features.normal;
    Eigen::Vector3d slide;
    // g and the slide only where they are used (the trace, friction).
    const double g = energy || mu > 0.0 ? violation(pair, p, mu > 0.0 ? &slide : nullptr) : 0.0;
    // Coulomb friction μλ against the closest points' slide over the step, as L-BFGS's energy.
    if (mu > 0.0) add_friction(mu * pair.force, slide, force);
    for (int k = 0; k < 4; ++k) {
      const double beta = pair.features.beta[k];
      if (beta != 0.0) rhs_rows_[pair.features.vertex[k]] += beta * force;
    }
    // The work the force does against the pair's gap, for the convergence trace.
    if (energy) sum -= pair.force * (pair.features.target - g);
  }
  if (packed) unpack_rows(rhs_rows_, rhs);
  if (energy) *energy += sum;
  solve_ms_ += stopwatch.milliseconds();
}

double SelfContactTerm::add_energy(const StepContext& /*step*/, const Eigen::MatrixXd& p,
                                   Eigen::MatrixXd* gradient) const {
  if (!on_) return 0.0;
  double energy = 0.0;
  for (const Pair& pair : pairs_) {
    if (!(pair.stiffness > 0.0)) continue;
    Eigen::Vector3d slide;
    const double g = violation(pair, p, pair.friction > 0.0 ? &slide : nullptr);
    const double pressed = std::max(0.0, g + pair.force / pair.stiffness);
    Eigen::Vector3d force = Eigen::Vector3d::Zero();  // −∂E/∂q, q the pair's Σβₖpₖ
    if (pressed > 0.0) {
      energy += 0.5 * pair.stiffness * pressed * pressed;
      force = pair.stiffness * pressed * pair.features.normal;
    }
    if (pair.friction > 0.0) energy += add_friction(pair.friction, slide, force);
    if (!gradient) continue;
    for (int k = 0; k < 4; ++k) {
      const double beta = pair.features.beta[k];
      if (beta != 0.0) gradient->row(pair.features.vertex[k]) -= beta * force.transpose();
    }
  }
  return energy;
}

double SelfContactTerm::add_friction(double strength, const Eigen::Vector3d& slide,
                                     Eigen::Vector3d& force) const {
  // Huber's function of the slide's length: below ε = friction_width() a stiff spring (static
  // friction), beyond it a constant pull `strength` (Coulomb).
  const double epsilon = friction_width(), length = slide.norm();
  if (length < epsilon) {
    force -= (strength / epsilon) * slide;
    return strength * length * length / (2.0 * epsilon);
  }
  force -= (strength / length) * slide;
  return strength * (length - 0.5 * epsilon);
}

int SelfContactTerm::separate(const StepContext& step, Eigen::MatrixXd& p) {
  // One Gauss-Seidel sweep over the pairs: each pair short of its gap is pushed apart along its
  // normal, its vertices weighted by inverse mass. The push also becomes the pair's force λ in
  // the next right-hand sides (what would have moved free masses as far), so that the global step
  // learns the contact instead of meeting it anew each iteration, and friction follows λ there
  // (add_targets). (Friction in the sweep, holding the slide back by μ times each push, was
  // friction as strong as the solve was far from converged: with 30 iterations the shipped pile
  // gained 96 J as it lay.)
  //
  // A pair with no force that was open by a slack s when last looked at stays open, and so does
  // nothing, until its vertices have travelled far enough to close it: g changes by at most
  // Σₖ|βₖ| times how far vertex k moved, and each vertex's travel (the length of its path since
  // the first sweep of the step or epoch) bounds that. Such pairs are passed over without a look
  // (most of a resting pile's); everything else is as if every pair were looked at.
  int pushed = 0;
  pack_rows(p, rows_);
  if (sweep_fresh_ || travel_.size() != rows_.size() || last_rows_.size() != rows_.size()) {
    travel_.assign(rows_.size(), 0.0);
    for (Pair& pair : pairs_)
      pair.slack = -1.0;
    sweep_fresh_ = false;
  } else {
    for (std::size_t v = 0; v < rows_.size(); ++v)
      travel_[v] += (rows_[v] - last_rows_[v]).norm();
  }
  for (Pair& pair : pairs_) {
    if (!(pair.stiffness > 0.0)) continue;
    const SelfContactPair& f = pair.features;
    double travel = 0.0;
    for (int k = 0; k < 4; ++k)
      travel += std::abs(f.beta[k]) * travel_[f.vertex[k]];
    // A margin for rounding: a pair this close to closing is looked at.
    if (pair.force == 0.0 && pair.slack > 0.0 && travel - pair.travel_at < 0.999 * pair.slack)
      continue;
    const double g = violation(
        pair, [&](int v) -> const Eigen::Vector3d& { return rows_[v]; }, nullptr);
    // λ follows the pair: up by what had to be pushed, down as the gap opens beyond its target.
    pair.force = std::max(0.0, pair.force + pair.stiffness * g);
    pair.slack = -g;
    pair.travel_at = travel;
    if (!(g > 0.0)) continue;
    double weight = 0.0;
    for (int k = 0; k < 4; ++k) {
      const int v = f.vertex[k];
      if (f.beta[k] != 0.0 && !step.pinned[v]) weight += f.beta[k] * f.beta[k] / step.rest.m(v);
    }
    if (!(weight > 0.0)) continue;
    const Eigen::Vector3d push = (g / weight) * f.normal;
    for (int k = 0; k < 4; ++k) {
      const int v = f.vertex[k];
      if (f.beta[k] == 0.0 || step.pinned[v]) continue;
      const Eigen::Vector3d shift = (f.beta[k] / step.rest.m(v)) * push;
      rows_[v] += shift;
      travel_[v] += shift.norm();
    }
    ++pushed;
  }
  if (pushed > 0) unpack_rows(rows_, p);
  return pushed;
}

bool SelfContactTerm::limit_iterate(const StepContext& step, Eigen::MatrixXd& p) {
  const Stopwatch stopwatch;
  const int pushed = separate(step, p);
  heading_ = p;
  const int moved = clamp_to_bounds(x_, common_motion(p), bounds_, p);
  clamped_ += moved;
  pack_rows(p, last_rows_);  // the next sweep measures travel from here
  solve_ms_ += stopwatch.milliseconds();
  // The bounded iterate is free of crossings: the next epoch starts there, its reaches from where
  // the solve was heading.
  if (moved > 0 && epochs_ < max_epochs) {
    x_ = p;
    start_epoch(step, heading_);
  }
  // Whether p moved: L-BFGS then evaluates it again and starts its history anew.
  return pushed > 0 || moved > 0;
}

}  // namespace wobble

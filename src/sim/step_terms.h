#ifndef WOBBLE_SIM_STEP_TERMS_H
#define WOBBLE_SIM_STEP_TERMS_H

#include <Eigen/Core>
#include <vector>

#include "spring_network.h"

namespace wobble {

// What a force or a constraint sees of the step about to be taken (or just solved).
struct StepContext {
  const SpringNetwork& rest;        // rest shape, springs, render triangles, masses
  const Eigen::MatrixXd& current;   // #V by 3 pᵗ (m)
  const Eigen::MatrixXd& previous;  // #V by 3 pᵗ⁻ᐞᵗ (m)
  const std::vector<char>& pinned;  // #V flags
  double dt;                        // Δt (s)
  double time;                      // simulated time at the start of the step (s)
};

// Wall-clock time of the last step, split between the local step (springs), the global step
// (the prefactored solve) and the parts around them (ms).
struct StepTiming {
  double local_ms = 0.0;
  double global_ms = 0.0;
  double forces_ms = 0.0;          // wind
  double contact_ms = 0.0;         // collider projection and friction
  double self_detection_ms = 0.0;  // self-collision: the spatial grid and the pairs it finds
  double self_response_ms = 0.0;   // self-collision: pushing pairs apart, friction, the swept check
  double instruments_ms = 0.0;     // the convergence trace, while it is recorded
  double total_ms = 0.0;
};

// The stepper's two hooks. Neither may change Q: forces act through f_ext (explicit, evaluated
// once at the start of a step), constraints move the solved positions after the iterations.

// Adds (or, for the course's wind, partly replaces) external forces, #V by 3 in N, before a step.
// `fext` arrives holding gravity.
class ForceTerm {
 public:
  virtual ~ForceTerm() = default;
  virtual void apply_forces(const StepContext& step, Eigen::MatrixXd& fext) const = 0;
};

// Moves the step's solved positions `next` (#V by 3, m) to satisfy a constraint the springs do
// not know about (contact), after the last iteration; it may also add a penalty to the
// right-hand side of each global solve. `end_step` is called once the step is accepted. The
// Simulation calls its constraints in a fixed order: colliders, then self-collision.
class PositionConstraint {
 public:
  virtual ~PositionConstraint() = default;
  // rhs (#V by 3) of the next global solve, given the iterate p; Qdiag is Q's diagonal.
  virtual void add_penalty(const Eigen::MatrixXd& /*p*/, const Eigen::VectorXd& /*Qdiag*/,
                           Eigen::MatrixXd& /*rhs*/) {}
  virtual void project(const StepContext& step, Eigen::MatrixXd& next) = 0;
  virtual void end_step() {}
  // Vertices the last project() moved: while any did, the next step is in contact.
  virtual int contact_count() const { return 0; }
  // Its share of the last step's time, written into its fields of `timing`.
  virtual void report_timing(StepTiming& /*timing*/) const {}
};

}  // namespace wobble

#endif

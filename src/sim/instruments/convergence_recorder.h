#ifndef WOBBLE_SIM_INSTRUMENTS_CONVERGENCE_RECORDER_H
#define WOBBLE_SIM_INSTRUMENTS_CONVERGENCE_RECORDER_H

#include "convergence_trace.h"
#include "step_observer.h"

namespace wobble {

// Records each step's ConvergenceTrace: the energy and gradient norm of every iterate, cleared
// at the start of each step. With room reserved for `max_iterations` + 1 entries, recording
// allocates nothing per iteration.
class ConvergenceRecorder : public StepObserver {
 public:
  void reserve(int max_iterations);
  // The next steps' force scale (ConvergenceTrace::force_scale, N).
  void set_force_scale(double force_scale) { force_scale_ = force_scale; }

  bool wants_measures() const override { return true; }
  void begin_step(const char* solver, bool accelerated) override;
  void measured(double energy, double gradient_norm) override;

  // The trace of the last step recorded (empty before one).
  const ConvergenceTrace& trace() const { return trace_; }

 private:
  ConvergenceTrace trace_;
  double force_scale_ = 0.0;
};

}  // namespace wobble

#endif

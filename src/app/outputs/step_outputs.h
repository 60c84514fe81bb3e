#ifndef WOBBLE_APP_OUTPUTS_STEP_OUTPUTS_H
#define WOBBLE_APP_OUTPUTS_STEP_OUTPUTS_H

#include "app/outputs/instrument_csv.h"
#include "app/outputs/obj_sequence.h"
#include "app/outputs/run_statistics.h"

namespace wobble {

class Simulation;

// What a run writes of each accepted step, the same way in every mode: the OBJ of its positions
// (--export-obj-sequence), its rows of the convergence and energy CSVs, and its timing for
// --stats. It observes the simulation's steps: the window and headless images attach after_step
// to the viewer's (ViewerSession::set_step_observer, on whichever thread steps), a headless run
// without images calls it after each step. Each step is numbered by Simulation::steps_taken.
class StepOutputs {
 public:
  // Both must outlive it; `stats`: keep each step's timing.
  StepOutputs(const ObjSequence& obj_sequence, InstrumentCsv& instruments, bool stats)
      : obj_sequence_(obj_sequence), instruments_(instruments), stats_(stats) {}

  void after_step(const Simulation& simulation);
  // Room for `steps` steps' timings, so that keeping them allocates nothing per step.
  void reserve(long steps) {
    if (stats_) times_.reserve(steps);
  }
  const StepTimes& times() const { return times_; }

 private:
  const ObjSequence& obj_sequence_;
  InstrumentCsv& instruments_;
  bool stats_;
  StepTimes times_;
};

}  // namespace wobble

#endif

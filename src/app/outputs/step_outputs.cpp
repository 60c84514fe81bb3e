#include "app/outputs/step_outputs.h"

#include "sim/simulation.h"

namespace wobble {

void StepOutputs::after_step(const Simulation& simulation) {
  const long step = simulation.steps_taken();
  obj_sequence_.write(step, simulation.positions(), simulation.rest());
  instruments_.record(step, simulation);
  if (stats_) times_.add(simulation.last_step_timing());
}

}  // namespace wobble

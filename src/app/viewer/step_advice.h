#ifndef WOBBLE_APP_VIEWER_STEP_ADVICE_H
#define WOBBLE_APP_VIEWER_STEP_ADVICE_H

#include <string>

#include "sim/simulation.h"

namespace wobble {

// What the viewer knows about a step that was rolled back, to tell the user what to try.
struct FailedStep {
  StepStatus status = StepStatus::ok;
  long step = 1;                  // 1 for the scene's first step
  bool initial_velocity = false;  // the scene starts moving (its initial_velocity is not zero)
  bool dragging = false;          // the mouse (or a scripted drag) held a vertex
  double stiffness_ratio = 0.0;   // k Δt² / (smallest vertex mass): springs against inertia
  double dt = 0.0;                // s
};

// One sentence for the banner: what happened and the advice that fits the likely cause (a drag
// too fast, the scene's initial velocity at its first step, springs far stiffer than the
// masses' inertia, or else dt and the iterations).
std::string describe_failed_step(const FailedStep& failed);

// k Δt² / m for the smallest positive mass m: above about 10³ the local-global iterations barely
// move a step towards its minimum, and a fixed count leaves it far from it.
double stiffness_ratio(const Simulation& simulation);

}  // namespace wobble

#endif

#ifndef WOBBLE_APP_WEB_STEP_POSITIONS_H
#define WOBBLE_APP_WEB_STEP_POSITIONS_H

#include <ostream>

#include "app/cli/command_line.h"

namespace wobble {

// The positions after `command.frames` steps (default 60) of the scene the command line names,
// with its --k, --dt and --iterations, as a headless run takes them (Simulation::step, no GL),
// written to `out` as JSON: {"scene", "frames", "step_ms_median" (wall-clock milliseconds of
// the median step), "diagonal" (of the rest shape's bounding box, m), "positions" (#V by 3, m,
// row-major, 17 significant digits)}. The same program built natively and for WebAssembly shows
// whether both compute the same numbers (tests/web/compare_positions.py).
void step_positions(const CommandLine& command, std::ostream& out);

}  // namespace wobble

#endif

#ifndef WOBBLE_APP_HEADLESS_RUN_HEADLESS_H
#define WOBBLE_APP_HEADLESS_RUN_HEADLESS_H

#include <iosfwd>

#include "app/cli/command_line.h"

namespace wobble {

// Run the requested scene without a window: build it, apply the command line's parameter
// overrides, take the requested number of steps, then export the OBJ and print the statistics
// if asked. With --screenshot or --record, each frame is also rendered through EGL into an
// offscreen buffer (the window's renderer) and the images written; long recordings report
// progress on `progress`. Output paths are checked before the first step. Returns the exit code.
// Throws InputError (bad scene, parameters or path), OutputError (a write failed),
// ContextError (no EGL context) or std::runtime_error (non-finite positions).
int run_headless(const CommandLine& command, std::ostream& out, std::ostream& progress);

}  // namespace wobble

#endif

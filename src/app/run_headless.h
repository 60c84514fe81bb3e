#ifndef WOBBLE_APP_RUN_HEADLESS_H
#define WOBBLE_APP_RUN_HEADLESS_H

#include <iosfwd>

#include "command_line.h"

namespace wobble {

// Simulate the requested scene without a window: build it, apply the command line's parameter
// overrides, take the requested number of steps, then export the OBJ and print the statistics
// if asked. Output paths are checked before the first step. Returns the process exit code.
// Throws InputError (bad scene or parameters), OutputError (a write failed) or
// std::runtime_error (the simulation produced non-finite positions).
int run_headless(const CommandLine& command, std::ostream& out);

}  // namespace wobble

#endif

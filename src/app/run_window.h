#ifndef WOBBLE_APP_RUN_WINDOW_H
#define WOBBLE_APP_RUN_WINDOW_H

#include <iosfwd>

#include "command_line.h"

namespace wobble {

// The interactive viewer: a resizable window with the ImGui panel, running until it is closed,
// Esc is pressed, or --frames frames have been shown. One time step per displayed frame.
// --screenshot writes the last frame, panel included. Throws ContextError when no window can be
// opened (no display), InputError for bad input, OutputError when an image cannot be written.
int run_window(const CommandLine& command, std::ostream& progress);

}  // namespace wobble

#endif

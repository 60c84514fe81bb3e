#ifndef WOBBLE_APP_WINDOW_RUN_WINDOW_H
#define WOBBLE_APP_WINDOW_RUN_WINDOW_H

#include <iosfwd>

#include "app/cli/command_line.h"

namespace wobble {

// The interactive viewer: a resizable window with the ImGui panel, running until it is closed
// (Ctrl+Q or the close button) or, with --frames N, until the state after step N is drawn. The
// simulation steps on a thread of its own while the UI draws the latest finished state (see
// Viewer). --screenshot writes the last frame, panel included; --stats prints one JSON line on
// `out` at the end. Throws ContextError when no window can be opened (no display), InputError
// for bad input, OutputError when an image cannot be written, runtime_error when a step of a
// --frames run fails.
int run_window(const CommandLine& command, std::ostream& out, std::ostream& progress);

}  // namespace wobble

#endif

#ifndef WOBBLE_APP_WEB_RUN_BROWSER_H
#define WOBBLE_APP_WEB_RUN_BROWSER_H

#include <string>
#include <vector>

#include "app/cli/command_line.h"

namespace wobble {

// The browser's window loop (emscripten, WebGL 2): the same Viewer and the same frame as the
// window (draw_frame, app/viewer/frame_loop.h), called once per animation frame by
// emscripten_set_main_loop instead of a while loop, since a page must return to the browser
// between frames. The steps run on the caller (a single-threaded page has no stepping thread), as
// many a frame as keep up with the wall clock. The canvas follows the size of the browser's
// window. `messages` (what the address got wrong) are told on the page, among the panel's notes
// and on the console. With `bench` (?bench), the page measures the step once it shows the scene
// (step_positions.h) and says the result. Returns at once; the loop goes on after main returns.
void run_browser(const CommandLine& command, const std::vector<std::string>& messages = {},
                 bool bench = false);

}  // namespace wobble

#endif

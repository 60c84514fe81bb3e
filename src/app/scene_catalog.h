#ifndef WOBBLE_APP_SCENE_CATALOG_H
#define WOBBLE_APP_SCENE_CATALOG_H

#include <iosfwd>
#include <string>
#include <vector>

#include "command_line.h"
#include "sim/scene.h"

namespace wobble {

// What the scene picker offers: the built-in scenes, then the scene files in Wobble's assets/
// folder (when it is where the build found it), as sources load_scene accepts.
std::vector<std::string> scene_catalog();

// The short name the picker shows for a source: a built-in name, or a file's name without its
// folder and extension.
std::string scene_label(const std::string& source);

// Load the scene the command line names. Its notes are not said yet: a refusal must be the
// only line on stderr, so they wait until everything the scene needs has been accepted.
Scene open_scene(const CommandLine& command);

// Say on `out` (stderr) what the loader chose for the user, one "wobble: note: ..." line each,
// with control characters escaped (a note may quote a key from the file).
void print_notes(const Scene& scene, std::ostream& out);

}  // namespace wobble

#endif

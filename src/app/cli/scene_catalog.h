#ifndef WOBBLE_APP_CLI_SCENE_CATALOG_H
#define WOBBLE_APP_CLI_SCENE_CATALOG_H

#include <iosfwd>
#include <string>
#include <vector>

#include "app/cli/command_line.h"
#include "sim/input_error.h"
#include "sim/scene.h"

namespace wobble {

// What the scene picker offers: the built-in scenes, then the scene files in Wobble's assets/
// folder and its subfolders (assets/course/), when it is where the build found it, as sources
// load_scene accepts.
std::vector<std::string> scene_catalog();

// The short name the picker shows for a source: a built-in name, or a file's name without its
// folder and extension.
std::string scene_label(const std::string& source);

// What the picker says of a source beside its label: a built-in scene's description, a scene
// file's "description" key, or for a course scene (assets/course/) its mesh, k and pins. Empty
// when the file says nothing or cannot be read (the picker opens it and says why then).
std::string scene_description(const std::string& source);
// Whether `source` is one of the course's scenes (a file in a folder named course).
bool is_course_scene_source(const std::string& source);

// Load the scene the command line names, with its --damping, --friction and --wind applied
// (apply_scene_overrides; --k, --dt and the rest are applied where the simulation starts). Its
// notes are not said yet: a refusal must be the only line on stderr, so they wait until
// everything the scene needs has been accepted.
Scene open_scene(const CommandLine& command);

// Say on `out` (stderr) what the loader chose for the user, one "wobble: note: ..." line each,
// with control characters escaped (a note may quote a key from the file).
void print_notes(const Scene& scene, std::ostream& out);

// Runs `start`, which starts the simulation of the scene `source` names, and puts `source` in
// front of the message of an InputError it throws: those say only what is wrong with the
// springs (a Cholesky factor over Wobble's limits), not which file gave them.
template <typename Start>
auto naming_scene(const std::string& source, Start start) -> decltype(start()) {
  try {
    return start();
  } catch (const InputError& error) {
    throw InputError(source + ": " + error.what());
  }
}

}  // namespace wobble

#endif

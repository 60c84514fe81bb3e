#ifndef WOBBLE_IO_LOAD_SCENE_H
#define WOBBLE_IO_LOAD_SCENE_H

#include <string>

#include "io/missing_texture.h"
#include "sim/scene.h"

namespace wobble {

// The scene `source` names: a built-in scene ("cloth", "jelly"), or a file:
//   .json         the course's scene format (keys "obj" and "b") or Wobble's own ("mesh")
//   .obj          a bare surface: area masses (0.25 kg/m²), k = 400, its top-most vertices
//                 pinned; with `fill`, filled with tetrahedra and simulated as a jelly
//   .mesh, .node, .ele   a tetrahedral mesh: volume masses (200 kg/m³), k = 1500, its lowest
//                 vertices pinned
// What was chosen for the user is recorded in scene.notes. Throws InputError with one line naming
// the file and the line or key at fault.
// A scene file's texture that cannot be read refuses the scene, unless `missing_texture` says to
// note it (scene.notes) and open the scene without it: the page does, for files dropped onto it
// without the picture their scene names.
Scene load_scene(const std::string& source, bool fill = false,
                 MissingTexture missing_texture = MissingTexture::refuse);

}  // namespace wobble

#endif

#ifndef WOBBLE_IO_WRITE_WOBBLE_SCENE_H
#define WOBBLE_IO_WRITE_WOBBLE_SCENE_H

#include <nlohmann/json.hpp>
#include <string>

#include "sim/scene.h"

namespace wobble {

// Save `scene` as a Wobble scene file at `json_path` (e.g. saved.json) with its mesh beside it
// (saved.obj, the same name with the extension .obj), so that load_scene(json_path) gives back,
// bit for bit, the network (V, E in the same order and direction, F, m), the pins (as a sorted
// set), every SimulationParams field but single_precision_solve_above (always the default
// whenever a scene is loaded), the initial velocity, uv, colours and camera. The texture is
// referenced relative to the saved file when it lies in that file's folder or below, otherwise
// by its absolute path. The notes are not saved.
//
// The mesh is an OBJ of `v` lines (shortest round-trip decimals), one `vt` per vertex when the
// scene has uv, one `f a b c` per row of F, then one two-vertex `f i j` per row of E; the scene
// sets mesh.polygon_springs false so that the triangles give no springs of their own, and
// material.vertex_masses so that every mass is stored as it is.
//
// Both files are written atomically (io/atomic_file.h): the mesh first, then the scene; if the
// scene cannot be written, a mesh file that did not exist before is removed again.
//
// Throws InputError naming `json_path` and what is wrong, before writing anything, when a file
// cannot be written there (its folder does not exist, it is a folder, ...), when the mesh file
// would be `json_path` itself (it ends in .obj), or when the scene holds something the format
// cannot state: an initial velocity that is neither the same for every vertex nor a sway (see
// docs/scenes.md). Throws OutputError when writing fails midway.
void write_wobble_scene(const std::string& json_path, const Scene& scene);

// The scene's JSON object, naming `mesh_file` as its mesh and `texture` (already made relative
// or absolute) as its texture. Throws InputError as write_wobble_scene does for what the format
// cannot state.
nlohmann::json wobble_scene_json(const Scene& scene, const std::string& mesh_file,
                                 const std::string& texture);

// The text of the mesh file that write_wobble_scene writes for `scene`.
std::string wobble_scene_obj_text(const Scene& scene);

}  // namespace wobble

#endif

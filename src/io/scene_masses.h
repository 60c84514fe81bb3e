#ifndef WOBBLE_IO_SCENE_MASSES_H
#define WOBBLE_IO_SCENE_MASSES_H

#include <string>

#include "io/json_fields.h"
#include "io/load_mesh.h"

namespace wobble {

// Turn the mass weights of `mesh` (areas, volumes or ones, see LoadedMesh) into masses in kg as
// a Wobble scene's `material` says: `density` (per unit of what the weights measure; by default
// 0.25 kg/m² for surfaces, 200 kg/m³ for volumes, 0.01 kg a vertex for lines), `mass` (the total,
// spread like the density), or `vertex_masses` (one mass for every vertex, replacing the
// weights: how a saved scene stores its masses exactly). At most one of the three. Throws
// InputError naming the key and what was expected; for a mesh whose faces all have zero area
// (LoadedMesh::no_area) unless `vertex_masses` gives the masses, naming `mesh_name` (how a
// message names the mesh: "scene.json: mesh.file 'flat.obj'").
void scene_masses(JsonFields& material, LoadedMesh& mesh, const std::string& mesh_name);

}  // namespace wobble

#endif

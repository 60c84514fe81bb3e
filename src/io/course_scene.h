#ifndef WOBBLE_IO_COURSE_SCENE_H
#define WOBBLE_IO_COURSE_SCENE_H

#include <nlohmann/json_fwd.hpp>
#include <string>

#include "io/missing_texture.h"
#include "sim/scene.h"

namespace wobble {

// The graphics course's scene format, loaded so that Wobble reproduces the course's reference
// program exactly. A course scene is a JSON object:
//
//   "obj"  OBJ mesh, relative to the JSON file (required)
//   "b"    pinned vertices, a list of 1-based indices into the OBJ's vertices (required)
//   "k"    spring stiffness, a positive number (required)
//   "m"    one mass for every vertex, a positive number (optional)
//   "png"  texture image, relative to the JSON file (optional); it is read whole and checked
//          when the scene loads (see texture_problem), so a bad or damaged texture is refused
//          whether or not it is drawn
//   "bc"   boundary conditions: not supported, refused
//
// Any other key is refused (InputError naming the file and the key). Whole numbers (`b`) may
// be spelt in any JSON way that is exactly whole: 4, 4.0, 4e0. The reference program's rules, which
// the Scene carries out:
//   springs    every pair of vertices of the faces of 3 or more vertices, once; every
//              two-vertex face as written, a repeated one being a second spring (the course's
//              E = F); `l` segments like two-vertex faces (see face_springs)
//   masses     "m" if given, else each vertex's lumped Voronoi area (see voronoi_masses) of the
//              fan-triangulated faces; a vertex in no triangle then has no mass and the scene
//              is refused, asking for "m"
//   gravity    a force of 9.8 down y on every vertex, whatever its mass (force_per_vertex)
//   step       dt = 1/30, 50 local-global iterations, pin weight 1e10, pins held at their rest
//              positions, starting at rest
//   render     the faces with 3 or more vertices, fan-triangulated with their winding
//   texture    "png" as the look's texture, with each vertex's first `vt` as its uv

// True when `object` is a JSON object with both "obj" and "b": the course's format.
bool is_course_scene(const nlohmann::json& object);

// Build the Scene of an already parsed course scene read from json_path (which names it, and
// which "obj" and "png" are relative to). Scene::name is the JSON file's stem.
// Throws InputError with a one-line message naming the JSON file and the key (or the OBJ file
// and its line) and what was expected. A "png" that cannot be read is refused, or noted and left
// out (`missing_texture`).
Scene load_course_scene(const std::string& json_path, const nlohmann::json& object,
                        MissingTexture missing_texture = MissingTexture::refuse);

// Read and parse json_path, then load it as above. Malformed JSON throws InputError
// "PATH: line L: malformed JSON: ...".
Scene load_course_scene(const std::string& json_path);

}  // namespace wobble

#endif

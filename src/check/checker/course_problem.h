#ifndef WOBBLE_CHECK_COURSE_PROBLEM_H
#define WOBBLE_CHECK_COURSE_PROBLEM_H

#include <string>

#include "check_scene.h"

// Load a scene of the course's format for the checker: a JSON object with
//   "obj"  OBJ mesh, relative to the JSON file
//   "b"    pinned vertices, 1-based indices into the OBJ's vertices
//   "k"    stiffness (N/m)
//   "m"    mass of every vertex (kg), optional: 1 kg without it
// Springs are the OBJ's two-vertex faces as written (`f i j`, or `l` segments) when it has no
// larger face, else every pair of vertices of each face, once. Gravity is 9.8 N down y on every
// vertex and dt = 1/30 s, as in the course's program; the scene starts at rest.
//
// This is not Wobble's course loader (src/io): the checker hands the student and the reference
// the same V and E, so exact fidelity to the course (Voronoi masses, repeated springs) does not
// matter here, and the checker stays a program of Eigen and nlohmann-json alone.
// Throws std::runtime_error "PATH: what is wrong" on a missing or malformed file.
CheckScene load_course_problem(const std::string& json_path, int steps);

#endif

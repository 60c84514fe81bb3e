#ifndef WOBBLE_CHECK_CHECK_PRELUDE_H
#define WOBBLE_CHECK_CHECK_PRELUDE_H

// What every student file compiled by scripts/check-assignment.sh starts with, before its own
// first line: the Eigen and standard headers the assignment's files use. The script compiles it
// once into a precompiled header in its cache, so each student file skips parsing Eigen (about a
// third of its compile time); a file that includes these again gets them from the include
// guards.
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#endif

#ifndef WOBBLE_APP_STUDENT_STUDENT_SERVER_H
#define WOBBLE_APP_STUDENT_STUDENT_SERVER_H

#include <string>

namespace wobble {

// wobble --student DIR: builds, with scripts/check-assignment.sh --build-step-server, the step
// server made of DIR's fast_mass_springs_step_sparse.cpp (see student_step.h), and returns the
// server's path. The build goes through the checker's cache, so a second start is quick. Throws
// InputError naming --student and DIR with the script's first line of explanation when the folder
// is missing, a file is missing or the student's code does not compile.
std::string build_student_step_server(const std::string& folder);

}  // namespace wobble

#endif

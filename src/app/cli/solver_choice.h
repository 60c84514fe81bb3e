#ifndef WOBBLE_APP_CLI_SOLVER_CHOICE_H
#define WOBBLE_APP_CLI_SOLVER_CHOICE_H

#include <string>
#include <vector>

namespace wobble {

// The step solvers as the program offers them: by their registered names
// (sim/solver/solver_registry.h: "local-global", "lbfgs") on the command line, in scene files and
// in --compare, and by their labels ("local-global", "L-BFGS") in the panel, the plots and the
// split view's corners.

// The registered names, in the registry's order; the first is the default.
std::vector<std::string> solver_names();
// Where `name` is in solver_names(), or 0 (the default) for a name not registered.
int solver_index(const std::string& name);

// How a class reads the solver: "L-BFGS" for "lbfgs", the registered name otherwise, with
// " (Chebyshev)" when `chebyshev` is on and the solver takes it.
std::string solver_label(const std::string& name, bool chebyshev = false);
// Whether Chebyshev acceleration applies to the solver (local-global only).
bool solver_takes_chebyshev(const std::string& name);

// `text` as a registered solver's name, or InputError "WHAT: expected local-global or lbfgs, got
// 'TEXT'" (WHAT: "--solver", "--compare: solver").
std::string parse_solver(const std::string& what, const std::string& text);

}  // namespace wobble

#endif

// The step solvers a SimulationParams::solver may name. Adding one: its own files, one line here.
#include "sim/input_error.h"
#include "sim/solver/lbfgs_solver.h"
#include "sim/solver/local_global_solver.h"
#include "sim/solver/solver_registry.h"

namespace wobble {

const std::vector<StepSolverEntry>& registered_step_solvers() {
  static const std::vector<StepSolverEntry> solvers = {
      {"local-global", make_local_global_solver},
      {"lbfgs", make_lbfgs_solver},
  };
  return solvers;
}

void validate_step_solver(const std::string& name) {
  std::string names;
  for (const StepSolverEntry& entry : registered_step_solvers()) {
    if (name == entry.name) return;
    names += (names.empty() ? "\"" : ", \"") + std::string(entry.name) + "\"";
  }
  throw InputError("solver: expected one of " + names + ", got \"" + name + "\"");
}

std::unique_ptr<StepSolver> make_step_solver(const std::string& name, Eigen::Index vertices) {
  validate_step_solver(name);
  for (const StepSolverEntry& entry : registered_step_solvers()) {
    if (name == entry.name) return entry.make(vertices);
  }
  return nullptr;  // not reached: validated above
}

}  // namespace wobble

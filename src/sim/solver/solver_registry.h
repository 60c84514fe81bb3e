#ifndef WOBBLE_SIM_SOLVER_SOLVER_REGISTRY_H
#define WOBBLE_SIM_SOLVER_SOLVER_REGISTRY_H

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

namespace wobble {

class StepSolver;

// Makes a solver for a network of `vertices` vertices (its buffers are #V by 3).
using StepSolverFactory = std::unique_ptr<StepSolver> (*)(Eigen::Index vertices);

struct StepSolverEntry {
  const char* name;  // as SimulationParams::solver, the command line and scene files spell it
  StepSolverFactory make;
};

// Every solver, one line each in registered_solvers.cpp; the first is the default.
const std::vector<StepSolverEntry>& registered_step_solvers();

// Throws InputError unless `name` is a registered solver's.
void validate_step_solver(const std::string& name);
// The solver registered as `name` (throws InputError for an unknown name).
std::unique_ptr<StepSolver> make_step_solver(const std::string& name, Eigen::Index vertices);

}  // namespace wobble

#endif

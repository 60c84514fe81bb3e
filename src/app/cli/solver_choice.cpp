#include "app/cli/solver_choice.h"

#include "sim/input_error.h"
#include "sim/settings/setting_registry.h"
#include "sim/settings/simulation_params.h"
#include "sim/solver/solver_registry.h"

namespace wobble {

std::vector<std::string> solver_names() {
  std::vector<std::string> names;
  for (const StepSolverEntry& entry : registered_step_solvers())
    names.emplace_back(entry.name);
  return names;
}

int solver_index(const std::string& name) {
  const std::vector<std::string> names = solver_names();
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return static_cast<int>(i);
  }
  return 0;
}

bool solver_takes_chebyshev(const std::string& name) {
  // As the declaration of chebyshev says (sim/settings/built_in_settings.cpp).
  SimulationParams params;
  params.solver = name;
  return find_setting("chebyshev")->applies(params);
}

std::string solver_label(const std::string& name, bool chebyshev) {
  std::string label = find_setting("solver")->choice_label(name);
  if (chebyshev && solver_takes_chebyshev(name)) label += " (Chebyshev)";
  return label;
}

std::string parse_solver(const std::string& what, const std::string& text) {
  const std::vector<std::string> names = solver_names();
  std::string expected;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == text) return text;
    expected += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  }
  throw InputError(what + ": expected " + expected + ", got '" + text + "'");
}

}  // namespace wobble

#include "app/cli/compare_settings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "app/cli/solver_choice.h"
#include "sim/input_error.h"

namespace wobble {

namespace {

std::vector<std::string> split_settings(const std::string& text) {
  std::vector<std::string> parts;
  std::string part;
  for (const char c : text + ",") {
    if (c == ',' || c == ' ' || c == '\t') {
      if (!part.empty()) parts.push_back(part);
      part.clear();
    } else {
      part.push_back(c);
    }
  }
  return parts;
}

}  // namespace

CompareSettings parse_compare_settings(const std::string& text) {
  CompareSettings settings;
  const std::vector<std::string> parts = split_settings(text);
  if (parts.empty()) {
    throw InputError(
        "--compare: expected settings of the right side such as 'iterations=5', "
        "got '" +
        text + "'");
  }
  std::vector<std::string> named;
  for (const std::string& part : parts) {
    const std::size_t equals = part.find('=');
    if (equals == std::string::npos) {
      throw InputError("--compare: expected name=value, got '" + part + "'");
    }
    const std::string name = part.substr(0, equals), value = part.substr(equals + 1);
    // Named twice, a setting gives both sides theirs, the left side's first (read as the two
    // sides stand); a third time, which side was meant?
    const auto times = std::count(named.begin(), named.end(), name);
    if (times == 2) {
      throw InputError("--compare: " + name + " is given three times in '" + text +
                       "', expected it once (the right side) or twice (left, then right)");
    }
    named.push_back(name);
    if (times == 1) {
      // The first value moves to the left side, and this one is read for the right.
      settings.left.take(settings, name);
    }
    settings.set(name, value, "--compare");
  }
  return settings;
}

std::string describe_side(const SimulationParams& params, bool name_solver) {
  char text[160];
  const char* plural = params.iterations == 1 ? "" : "s";
  if (name_solver) {
    // A line of its own: "local-global (Chebyshev)" and the iterations would not fit beside
    // each other in a half beside the panel and the plots.
    std::snprintf(text, sizeof(text), "%s\n%d iteration%s\ndt %.3g ms, k %g N/m",
                  solver_label(params.solver, params.chebyshev).c_str(), params.iterations, plural,
                  1000.0 * params.dt, params.k);
  } else {
    std::snprintf(text, sizeof(text), "%d iteration%s, %s\ndt %.3g ms, k %g N/m", params.iterations,
                  plural, params.chebyshev ? "Chebyshev" : "plain", 1000.0 * params.dt, params.k);
  }
  return text;
}

CompareSettings default_compare_settings(const SimulationParams& left) {
  CompareSettings settings;
  settings.values["iterations"] = static_cast<double>(
      left.iterations >= 10 ? std::max(1, left.iterations / 10)
                            : std::min(Simulation::max_iterations, 10 * left.iterations));
  return settings;
}

}  // namespace wobble

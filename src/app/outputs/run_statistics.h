#ifndef WOBBLE_APP_OUTPUTS_RUN_STATISTICS_H
#define WOBBLE_APP_OUTPUTS_RUN_STATISTICS_H

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "sim/scene.h"
#include "sim/simulation.h"

namespace wobble {

// The wall-clock times of a run's steps (ms), as --stats reports them.
struct StepTimes {
  std::vector<double> step_ms, local_ms, global_ms;
  // Each term's figures (StepTiming::figures) by key (term_figure_key), in the order first seen.
  std::vector<std::pair<std::string, std::vector<double>>> figures;
  void reserve(long steps);
  void add(const StepTiming& timing);
};

// A term's figure as a key: its term, name and unit in snake case ("self_contact_detection_ms").
std::string term_figure_key(const TermFigure& figure);

// The median of `values` (0 when empty; the mean of the middle two for an even count).
double median(std::vector<double> values);

// --stats: the scene, the simulation's settings and factor, and the step times' medians (the
// docs/command-line.md lists the keys under --stats), with self-collision's: whether it is on, its
// thickness (m), the last step's self contacts; then the median of every term's figure, as
// KEY_median with term_figure_key's keys.
// Headless adds the render time, the window the UI's frame time.
nlohmann::ordered_json run_statistics(const Simulation& simulation, const Scene& scene, long frames,
                                      const StepTimes& times);

}  // namespace wobble

#endif

#ifndef WOBBLE_APP_HEADLESS_RUN_STATISTICS_H
#define WOBBLE_APP_HEADLESS_RUN_STATISTICS_H

#include <nlohmann/json.hpp>
#include <vector>

#include "sim/scene.h"
#include "sim/simulation.h"

namespace wobble {

// The wall-clock times of a run's steps (ms), as --stats reports them.
struct StepTimes {
  std::vector<double> step_ms, local_ms, global_ms;
  std::vector<double> self_detection_ms, self_response_ms;  // 0 while self-collision is off
  void reserve(long steps);
  void add(const StepTiming& timing);
};

// The median of `values` (0 when empty; the mean of the middle two for an even count).
double median(std::vector<double> values);

// --stats: the scene, the simulation's settings and factor, and the step times' medians (the
// docs/command-line.md lists the keys under --stats), with self-collision's: whether it is on, its
// thickness (m), the last step's self contacts and the medians of its detection and response times.
// Headless adds the render time, the window the UI's frame time.
nlohmann::ordered_json run_statistics(const Simulation& simulation, const Scene& scene, long frames,
                                      const StepTimes& times);

}  // namespace wobble

#endif

#include "app/web/step_positions.h"

#include <algorithm>
#include <iomanip>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/cli/scene_catalog.h"
#include "sim/simulation.h"

namespace wobble {

void step_positions(const CommandLine& command, std::ostream& out) {
  const Scene scene = open_scene(command);
  const SimulationParams params = command.settings.applied_to(scene.params);
  Simulation simulation(scene.network, scene.pins, params, scene.initial_velocity);
  const long frames = command.frames.value_or(60);
  std::vector<double> step_ms;
  for (long frame = 0; frame < frames; ++frame) {
    const StepStatus status = simulation.step();
    step_ms.push_back(simulation.last_step_timing().total_ms);
    if (status != StepStatus::ok) {
      throw std::runtime_error("frame " + std::to_string(frame + 1) + ": " +
                               Simulation::describe(status));
    }
  }
  const Eigen::MatrixXd& rest = scene.network.V;
  const double diagonal = (rest.colwise().maxCoeff() - rest.colwise().minCoeff()).norm();
  const Eigen::MatrixXd& positions = simulation.positions();
  std::sort(step_ms.begin(), step_ms.end());
  const double median_ms = step_ms.empty() ? 0.0 : step_ms[step_ms.size() / 2];
  out << std::setprecision(17) << "{\"scene\": \"" << scene.name << "\", \"frames\": " << frames
      << ", \"step_ms_median\": " << median_ms << ", \"diagonal\": " << diagonal
      << ", \"positions\": [";
  for (Eigen::Index i = 0; i < positions.rows(); ++i) {
    out << (i == 0 ? "" : ", ") << "[" << positions(i, 0) << ", " << positions(i, 1) << ", "
        << positions(i, 2) << "]";
  }
  out << "]}\n";
}

}  // namespace wobble

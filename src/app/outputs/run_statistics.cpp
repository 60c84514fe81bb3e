#include "app/outputs/run_statistics.h"

#include <algorithm>
#include <cctype>

#include "io/setting_json.h"
#include "sim/contact/self_contact_term.h"
#include "sim/parallel/worker_pool.h"
#include "sim/settings/setting_registry.h"

namespace wobble {

void StepTimes::reserve(long steps) {
  for (std::vector<double>* times : {&step_ms, &local_ms, &global_ms})
    times->reserve(steps);
}

std::string term_figure_key(const TermFigure& figure) {
  std::string key = std::string(figure.term) + "_" + figure.name;
  if (figure.unit[0] != '\0') key += std::string("_") + figure.unit;
  for (char& c : key) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return key;
}

void StepTimes::add(const StepTiming& timing) {
  step_ms.push_back(timing.total_ms);
  local_ms.push_back(timing.local_ms);
  global_ms.push_back(timing.global_ms);
  for (const TermFigure& figure : timing.figures) {
    const std::string key = term_figure_key(figure);
    auto found = std::find_if(figures.begin(), figures.end(),
                              [&](const auto& entry) { return entry.first == key; });
    if (found == figures.end()) {
      figures.emplace_back(key, std::vector<double>());
      found = figures.end() - 1;
      found->second.reserve(step_ms.capacity());
    }
    found->second.push_back(figure.value);
  }
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const std::size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + middle, values.end());
  if (values.size() % 2 == 1) return values[middle];
  const double upper = values[middle];
  return 0.5 * (upper + *std::max_element(values.begin(), values.begin() + middle));
}

nlohmann::ordered_json run_statistics(const Simulation& simulation, const Scene& scene, long frames,
                                      const StepTimes& times) {
  const SimulationParams& params = simulation.params();
  const std::vector<double>& step_ms = times.step_ms;
  nlohmann::ordered_json statistics = {
      {"scene", scene.name},
      {"vertices", scene.network.V.rows()},
      {"springs", scene.network.E.rows()},
      {"pinned", simulation.pin_count()},
      {"chebyshev_rho", simulation.chebyshev_spectral_radius()},
      {"frames", frames},
      {"precompute_ms", simulation.precompute_ms()},
      {"factor_nonzeros", simulation.factor_nonzeros()},
      {"factorization_work", simulation.factorization_work()},
      {"single_precision_solve", simulation.solves_in_single_precision()},
      {"step_ms_median", median(step_ms)},
      {"step_ms_min", step_ms.empty() ? 0.0 : *std::min_element(step_ms.begin(), step_ms.end())},
      {"step_ms_max", step_ms.empty() ? 0.0 : *std::max_element(step_ms.begin(), step_ms.end())},
      {"local_ms_median", median(times.local_ms)},
      {"global_ms_median", median(times.global_ms)},
      {"self_collision_thickness_kept",
       self_collision_thickness_kept(simulation.terms(),
                                     simulation.params().self_collision.thickness)},
      {"self_contacts",
       static_cast<int>(simulation.last_step_timing().figure("self-contact", "contacts"))},
      {"threads", shared_thread_setting().threads},
      {"threads_from", shared_thread_setting().source},
  };
  // Each setting --stats reports (sim/settings/setting_registry.h), by its key.
  for (const SettingSpec& spec : all_settings()) {
    if (spec.places & in_stats)
      statistics[setting_key(spec)] = setting_json(spec, spec.get(params));
  }
  for (const auto& [key, values] : times.figures)
    statistics[key + "_median"] = median(values);
  return statistics;
}

}  // namespace wobble

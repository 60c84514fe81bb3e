#include "app/viewer/side_settings.h"

#include <algorithm>
#include <cmath>

#include "app/cli/solver_choice.h"
#include "sim/settings/setting_registry.h"

namespace wobble {

namespace {

// `value`, unless the slider shows another: then the slider's.
double taken(double value, float shown) {
  return static_cast<float>(value) == shown ? value : static_cast<double>(shown);
}

}  // namespace

void show_settings(const SimulationParams& params, SideSliders& sliders, bool solid) {
  sliders.k = static_cast<float>(params.k);
  sliders.dt = static_cast<float>(params.dt);
  sliders.iterations = params.iterations;
  sliders.solver = solver_index(params.solver);
  sliders.chebyshev = params.chebyshev;
  sliders.added.clear();
  for (const SettingSpec& spec : added_settings()) {
    AddedSlider slider;
    slider.label = spec.label;
    slider.unit = spec.range.unit;
    slider.low = static_cast<float>(spec.range.low);
    slider.high = static_cast<float>(spec.range.high);
    slider.log_scale = spec.log_scale;
    slider.value = static_cast<float>(setting_value(params, spec.name));
    slider.shown = solid || !spec.solids_only;
    sliders.added.push_back(slider);
  }
}

SimulationParams settings_from_sliders(const SimulationParams& params, SideSliders& sliders,
                                       int most_iterations) {
  SimulationParams wanted = params;
  wanted.k = taken(params.k, sliders.k);
  wanted.dt = taken(params.dt, sliders.dt);
  sliders.iterations = std::min(sliders.iterations, most_iterations);
  wanted.iterations = sliders.iterations;
  wanted.solver = solver_names().at(sliders.solver);
  wanted.chebyshev = sliders.chebyshev;
  const std::vector<SettingSpec>& specs = added_settings();
  for (std::size_t i = 0; i < specs.size() && i < sliders.added.size(); ++i) {
    const SettingSpec& spec = specs[i];
    const double value = setting_value(params, spec.name);
    const double shown = taken(value, sliders.added[i].value);
    if (shown != value) {
      wanted.added_settings[spec.name] = std::clamp(shown, spec.range.low, spec.range.high);
    }
  }
  return wanted;
}

}  // namespace wobble

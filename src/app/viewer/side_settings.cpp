#include "app/viewer/side_settings.h"

#include <algorithm>
#include <cmath>

#include "sim/settings/setting_registry.h"

namespace wobble {

namespace {

// `value`, unless the control shows another: then the control's.
double taken(double value, float shown) {
  return static_cast<float>(value) == shown ? value : static_cast<double>(shown);
}

// The settings a side's controls show: those each side has its own of, in the panel.
bool on_a_side(const SettingSpec& spec) {
  return spec.per_side && (spec.places & in_panel) != 0;
}

SettingControl::Kind control_kind(SettingType type) {
  switch (type) {
    case SettingType::integer:
      return SettingControl::Kind::integer;
    case SettingType::toggle:
      return SettingControl::Kind::toggle;
    case SettingType::choice:
      return SettingControl::Kind::choice;
    case SettingType::number:
    case SettingType::vector:
      break;
  }
  return SettingControl::Kind::number;
}

}  // namespace

void show_settings(const SimulationParams& params, SideSliders& sliders, bool solid) {
  sliders.controls.clear();
  for (const SettingSpec& spec : all_settings()) {
    if (!on_a_side(spec) || spec.type == SettingType::vector) continue;
    SettingControl control;
    control.kind = control_kind(spec.type);
    control.name = spec.name;
    control.label = spec.label;
    control.help = spec.help;
    const bool ranged = spec.type == SettingType::number || spec.type == SettingType::integer;
    if (ranged) control.unit = spec.range.unit;
    const ValueRange& range =
        spec.panel_range.high > spec.panel_range.low ? spec.panel_range : spec.range;
    control.low = static_cast<float>(range.low);
    control.high = static_cast<float>(range.high);
    control.log_scale = spec.log_scale;
    control.format = spec.panel_format;
    const SettingValue value = spec.get(params);
    if (spec.type == SettingType::number) control.value = static_cast<float>(setting_number(value));
    if (spec.type == SettingType::integer) control.whole = static_cast<int>(setting_number(value));
    if (spec.type == SettingType::toggle) control.on = std::get<bool>(value);
    if (spec.type == SettingType::choice) {
      const std::vector<std::string> names = spec.choices();
      for (std::size_t i = 0; i < names.size(); ++i) {
        control.choices.push_back(spec.choice_label ? spec.choice_label(names[i]) : names[i]);
        if (names[i] == std::get<std::string>(value)) control.whole = static_cast<int>(i);
      }
    }
    // For each choice of the setting it goes with, whether it applies.
    const SettingSpec* with = *spec.applies_with ? find_setting(spec.applies_with) : nullptr;
    if (spec.applies && with && with->type == SettingType::choice) {
      control.applies_with = with->name;
      control.why_not = spec.why_not;
      for (const std::string& name : with->choices()) {
        SimulationParams other = params;
        with->set(other, name);
        control.applies_for.push_back(spec.applies(other) ? 1 : 0);
      }
    }
    control.course_locked = !spec.course_scene;
    control.shown = solid || !spec.solids_only;
    sliders.controls.push_back(control);
  }
}

SimulationParams settings_from_sliders(const SimulationParams& params, SideSliders& sliders,
                                       int most_iterations) {
  SimulationParams wanted = params;
  for (SettingControl& control : sliders.controls) {
    const SettingSpec* spec = find_setting(control.name);
    if (!spec) continue;
    // Only what a control changed is set: an added setting left alone stays unset.
    const SettingValue value = spec->get(params);
    const auto set = [&](const SettingValue& shown) {
      if (shown != value) spec->set(wanted, shown);
    };
    switch (spec->type) {
      case SettingType::number: {
        const double now = setting_number(value), shown = taken(now, control.value);
        // A float's rounding can fall just outside the range.
        if (shown != now) set(std::clamp(shown, spec->range.low, spec->range.high));
        break;
      }
      case SettingType::integer:
        // The work of a step is bounded by the mesh (Simulation::max_iterations_for_mesh).
        if (costs(spec->cost, SettingCost::step_work))
          control.whole = std::min(control.whole, most_iterations);
        set(static_cast<double>(control.whole));
        break;
      case SettingType::toggle:
        set(control.on);
        break;
      case SettingType::choice: {
        const std::vector<std::string> names = spec->choices();
        if (control.whole >= 0 && control.whole < static_cast<int>(names.size()))
          set(names[control.whole]);
        break;
      }
      case SettingType::vector:
        break;
    }
  }
  return wanted;
}

}  // namespace wobble

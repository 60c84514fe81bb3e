#include "app/viewer/side_settings.h"

#include <algorithm>
#include <cmath>

#include "app/interaction/environment_controls.h"
#include "sim/settings/setting_registry.h"

namespace wobble {

namespace {

// The settings a list of controls shows: those in the panel that each side has its own of, or
// those the two sides share.
bool in_part(const SettingSpec& spec, PanelPart part) {
  return (spec.places & in_panel) != 0 && spec.per_side == (part == PanelPart::each_side);
}

SettingControl::Kind control_kind(const SettingSpec& spec) {
  if (spec.panel_view == PanelView::speed_and_heading) return SettingControl::Kind::heading;
  switch (spec.type) {
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

void show_settings(const SimulationParams& params, SideSliders& sliders, bool solid,
                   PanelPart part) {
  sliders.controls.clear();
  for (const SettingSpec& spec : all_settings()) {
    if (!in_part(spec, part)) continue;
    if (spec.type == SettingType::vector && spec.panel_view == PanelView::value) continue;
    SettingControl control;
    control.kind = control_kind(spec);
    control.name = spec.name;
    control.label = *spec.panel_label ? spec.panel_label : spec.label;
    control.help = spec.help;
    const bool ranged = spec.type == SettingType::number || spec.type == SettingType::integer ||
                        spec.type == SettingType::vector;
    if (ranged) control.unit = *spec.panel_unit ? spec.panel_unit : spec.range.unit;
    const ValueRange& range =
        spec.panel_range.high > spec.panel_range.low ? spec.panel_range : spec.range;
    control.low = static_cast<float>(range.low);
    control.high = static_cast<float>(range.high);
    control.log_scale = spec.log_scale;
    control.format = spec.panel_format;
    const SettingValue value = spec.get(params);
    if (spec.type == SettingType::number)
      control.value = static_cast<float>(setting_number(value) * spec.panel_scale);
    if (control.kind == SettingControl::Kind::heading) {
      const Eigen::Vector3d& v = std::get<Eigen::Vector3d>(value);
      control.value = static_cast<float>(v.norm());
      control.heading = static_cast<float>(heading_degrees(v));
    }
    if (spec.panel_view == PanelView::strength) {
      const Eigen::Vector3d& v = std::get<Eigen::Vector3d>(value);
      control.value = static_cast<float>(v.norm());
      const Eigen::Vector3d along = v.norm() > 0.0 ? v : spec.number_along;
      for (int i = 0; i < 3; ++i)
        control.direction[i] = along.norm() > 0.0 ? along(i) / along.norm() : 0.0;
    }
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
    control.shown = (solid || !spec.solids_only) && (!spec.offered || spec.offered(params));
    control.shown_with = spec.shown_with;
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
        const double now = setting_number(value), scale = spec->panel_scale;
        const double shown = static_cast<float>(now * scale) == control.value
                                 ? now
                                 : static_cast<double>(control.value) / scale;
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
        // Turned on as a user turns it on (the wind over a calm scene: the breeze).
        if (control.on != std::get<bool>(value)) {
          if (control.on) {
            turn_on(*spec, wanted);
          } else {
            spec->set(wanted, false);
          }
        }
        break;
      case SettingType::choice: {
        const std::vector<std::string> names = spec->choices();
        if (control.whole >= 0 && control.whole < static_cast<int>(names.size()))
          set(names[control.whole]);
        break;
      }
      case SettingType::vector: {
        const Eigen::Vector3d& v = std::get<Eigen::Vector3d>(value);
        if (spec->panel_view == PanelView::strength) {
          if (static_cast<float>(v.norm()) != control.value) {
            const Eigen::Vector3d direction(control.direction[0], control.direction[1],
                                            control.direction[2]);
            set(static_cast<double>(control.value) * direction);
          }
          break;
        }
        if (control.kind != SettingControl::Kind::heading) break;
        if (static_cast<float>(v.norm()) != control.value ||
            static_cast<float>(heading_degrees(v)) != control.heading) {
          set(with_speed_and_heading(v, control.value, control.heading));
        }
        break;
      }
    }
  }
  return wanted;
}

}  // namespace wobble

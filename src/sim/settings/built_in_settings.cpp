// The simulation's built-in settings, one declaration each: the fields of SimulationParams that
// a user sets, with what each is called, takes and costs. Everything that sets or reads a
// setting loops over this list and the added settings (sim/settings/setting_registry.h); nothing
// else names them one by one.
#include <utility>

#include "sim/settings/setting_registry.h"
#include "sim/settings/simulation_params.h"
#include "sim/solver/solver_registry.h"

namespace wobble {

namespace {

// Binds a declaration to a field of SimulationParams: `field` is a lambda
// [](auto& params) -> auto& { return params.FIELD; }, which serves reading and writing alike. The
// value is kept in a SettingValue as `Stored`: double (a number or an integer), bool (a switch),
// std::string (a choice by name) or Eigen::Vector3d.
template <typename Stored, typename Field>
SettingSpec bound(SettingSpec spec, SettingType type, Field field) {
  spec.type = type;
  spec.get = [field](const SimulationParams& params) -> SettingValue {
    return static_cast<Stored>(field(params));
  };
  spec.set = [field](SimulationParams& params, const SettingValue& value) {
    using Type = std::decay_t<decltype(field(params))>;
    field(params) = static_cast<Type>(std::get<Stored>(value));
  };
  return spec;
}
template <typename Field>
SettingSpec number_field(SettingSpec spec, SettingType type, Field field) {
  return bound<double>(std::move(spec), type, field);
}
template <typename Field>
SettingSpec toggle_field(SettingSpec spec, Field field) {
  return bound<bool>(std::move(spec), SettingType::toggle, field);
}
template <typename Field>
SettingSpec vector_field(SettingSpec spec, Field field) {
  return bound<Eigen::Vector3d>(std::move(spec), SettingType::vector, field);
}
// A choice kept as a name (the solver's).
template <typename Field>
SettingSpec name_field(SettingSpec spec, std::vector<std::string> (*choices)(), Field field) {
  spec.choices = choices;
  return bound<std::string>(std::move(spec), SettingType::choice, field);
}

// A choice kept as an enumeration whose values are 0, 1, ... in the order of `choices()`.
template <typename Field>
SettingSpec enum_field(SettingSpec spec, std::vector<std::string> (*choices)(), Field field) {
  spec.type = SettingType::choice;
  spec.choices = choices;
  spec.get = [field, choices](const SimulationParams& params) -> SettingValue {
    return choices().at(static_cast<std::size_t>(field(params)));
  };
  spec.set = [field, choices](SimulationParams& params, const SettingValue& value) {
    const std::vector<std::string> names = choices();
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (names[i] == std::get<std::string>(value)) {
        field(params) = static_cast<std::decay_t<decltype(field(params))>>(i);
      }
    }
  };
  return spec;
}

std::vector<std::string> solver_choices() {
  std::vector<std::string> names;
  for (const StepSolverEntry& entry : registered_step_solvers())
    names.emplace_back(entry.name);
  return names;
}
// "L-BFGS" for "lbfgs": the panel's and the corners' word for a solver.
std::string solver_choice_label(const std::string& name) {
  return name == "lbfgs" ? "L-BFGS" : name;
}
// Chebyshev's semi-iterative acceleration applies to the local-global iteration alone (Wang 2015
// accelerates it; L-BFGS has its own history).
bool chebyshev_applies(const SimulationParams& params) {
  return params.solver == "local-global";
}
std::vector<std::string> gravity_model_choices() {
  return {"acceleration", "force_per_vertex"};  // GravityModel's order
}
std::vector<std::string> first_iterate_choices() {
  return {"current_positions", "inertial_prediction"};  // FirstIterate's order
}
std::vector<std::string> wind_model_choices() {
  return {"aerodynamic", "course"};  // WindModel's order
}

using Cost = SettingCost;
constexpr ValueRange no_range{0.0, 0.0, ""};
constexpr ValueRange iteration_range{1.0, limits::max_iterations, ""};

// Whether the split view's right side has its own value (what a side steps with: --compare
// sets it) or takes the left side's (the environment), and whether a course scene, which keeps
// the reference program's method, may take it.
enum Side : bool { shared = false, own = true };
enum Course : bool { refused = false, allowed = true };

// The declaration's words and where it reaches; the type and the field come with its binding.
SettingSpec setting(const char* name, const char* label, const char* help, ValueRange range,
                    double default_value, SettingCost cost, unsigned places, Side side,
                    Course course) {
  SettingSpec spec;
  spec.name = name;
  spec.label = label;
  spec.help = help;
  spec.range = range;
  spec.default_value = default_value;
  spec.cost = cost;
  spec.places = places;
  spec.per_side = side;
  spec.course_scene = course;
  return spec;
}

// The panel's control: moved by a factor a pixel (it spans decades), over `range` (narrower than
// the setting's own) and printed with `format`.
SettingSpec logarithmic(SettingSpec spec) {
  spec.log_scale = true;
  return spec;
}
SettingSpec in_the_panel(SettingSpec spec, ValueRange range, const char* format = "%.4g") {
  spec.panel_range = range;
  spec.panel_format = format;
  return spec;
}
SettingSpec labelled(SettingSpec spec, std::string (*label)(const std::string&)) {
  spec.choice_label = label;
  return spec;
}
// Where a scene file keeps it (SettingSpec::scene_path): the setting reaches files too.
SettingSpec in_files_at(SettingSpec spec, const char* path) {
  spec.places |= in_scene;
  spec.scene_path = path;
  return spec;
}
// A switch that is its section being in a scene file (SettingSpec::section_switch).
SettingSpec section_switch(SettingSpec spec, const char* section, bool keyed) {
  spec = in_files_at(spec, section);
  spec.section_switch = true;
  spec.switch_key = keyed;
  return spec;
}
SettingSpec needed(SettingSpec spec) {
  spec.needed_in_section = true;
  return spec;
}
SettingSpec pointing(SettingSpec spec, const Eigen::Vector3d& direction) {
  spec.number_along = direction;
  return spec;
}
SettingSpec turned_on_with(SettingSpec spec, void (*also)(SimulationParams&)) {
  spec.when_turned_on = also;
  return spec;
}
SettingSpec implying(SettingSpec spec, const char* name) {
  spec.implies = name;
  return spec;
}
// The panel's words for it, when not its label and unit: "wind (W)"; a thickness in "mm" (1000).
SettingSpec shown_as(SettingSpec spec, const char* label, const char* unit = "",
                     double scale = 1.0) {
  spec.panel_label = label;
  spec.panel_unit = unit;
  spec.panel_scale = scale;
  return spec;
}
SettingSpec offered_when(SettingSpec spec, bool (*offered)(const SimulationParams&)) {
  spec.offered = offered;
  return spec;
}
SettingSpec shown_beside(SettingSpec spec, const char* switch_name) {
  spec.shown_with = switch_name;
  return spec;
}
SettingSpec as_speed_and_heading(SettingSpec spec) {
  spec.panel_view = PanelView::speed_and_heading;
  return spec;
}
SettingSpec as_strength(SettingSpec spec) {
  spec.panel_view = PanelView::strength;
  return spec;
}
bool has_colliders(const SimulationParams& params) {
  return !params.contact.colliders.empty();
}
// The course's wind is a force with no speed or heading.
bool aerodynamic_wind(const SimulationParams& params) {
  return params.wind.model == WindModel::aerodynamic;
}

// The wind switched on over a calm scene blows the default breeze: the switch always shows wind.
void breeze_if_calm(SimulationParams& params) {
  const WindParams& wind = params.wind;
  if (!wind.on && wind.model == WindModel::aerodynamic && wind.velocity.isZero(0.0))
    params.wind = WindParams::default_breeze();
}

SettingSpec applies_only_with(SettingSpec spec, const char* with,
                              bool (*applies)(const SimulationParams&), const char* why_not) {
  spec.applies_with = with;
  spec.applies = applies;
  spec.why_not = why_not;
  return spec;
}

// Where each reaches: where the user has always met it. The rest reach Simulation::apply alone
// (and the scene's own readers, io/wobble_scene.cpp).
constexpr unsigned everywhere_but_files = on_command_line | in_address | in_panel | in_stats;
constexpr unsigned applied_only = 0;

std::vector<SettingSpec> declare_built_in_settings() {
  const SimulationParams d;  // the defaults
  // clang-format off
  return {
      // What each side of the split view steps with.
      in_files_at(in_the_panel(logarithmic(number_field(setting("k", "k",
          "Spring stiffness in N/m (scene default otherwise)",
          limits::stiffness, d.k, Cost::factorization, everywhere_but_files, own, allowed),
          SettingType::number, [](auto& p) -> auto& { return p.k; })),
          {1.0, 1e6, ""}, "%.1f"), "material.k"),
      in_the_panel(logarithmic(number_field(setting("dt", "dt",
          "Time step in seconds (scene default otherwise)",
          limits::time_step, d.dt, Cost::factorization | Cost::time_step, everywhere, own, allowed),
          SettingType::number, [](auto& p) -> auto& { return p.dt; })),
          {1.0 / 240.0, 1.0 / 15.0, ""}, "%.5f"),
      in_the_panel(number_field(setting("iterations", "iterations",
          "Local-global iterations per step",
          iteration_range, d.iterations, Cost::step_work, everywhere, own, allowed),
          SettingType::integer, [](auto& p) -> auto& { return p.iterations; }),
          {1.0, 100.0, ""}),
      labelled(name_field(setting("solver", "solver",
          "Step solver: local-global (the course's method, default) or lbfgs (L-BFGS, Liu et al. "
          "2017); the scene's otherwise",
          no_range, 0.0, Cost::solver | Cost::solver_state, everywhere, own, refused),
          solver_choices, [](auto& p) -> auto& { return p.solver; }),
          solver_choice_label),
      applies_only_with(toggle_field(setting("chebyshev", "Chebyshev acceleration",
          "Chebyshev acceleration of the local-global iterations (Wang 2015)",
          no_range, 0.0, Cost::solver_state, everywhere, own, refused),
          [](auto& p) -> auto& { return p.chebyshev; }),
          "solver", chebyshev_applies,
          "Chebyshev acceleration applies to the local-global iterations only"),
      // The environment, one for both sides.
      in_the_panel(logarithmic(number_field(setting("damping", "damping",
          "Damping in 1/s: velocities decay as (1 + C dt)^-steps (scene default otherwise, 0)",
          limits::damping, d.damping, Cost::factorization, everywhere, shared, refused),
          SettingType::number, [](auto& p) -> auto& { return p.damping; })),
          {0.0, 10.0, ""}, "%.3f"),
      offered_when(in_the_panel(in_files_at(number_field(setting("friction", "friction",
          "Coulomb friction coefficient against the colliders (scene default otherwise, 0)",
          limits::friction, d.contact.friction, Cost::value, on_command_line | in_address |
          in_panel, shared, refused),
          SettingType::number, [](auto& p) -> auto& { return p.contact.friction; }),
          "material.friction"), {0.0, 2.0, ""}, "%.2f"), has_colliders),
      shown_as(turned_on_with(section_switch(toggle_field(setting("wind", "wind",
          "Turn the wind on: the scene's, or a default breeze (course scenes: the course wind)",
          no_range, 0.0, Cost::terms, on_command_line | in_address | in_panel, shared, allowed),
          [](auto& p) -> auto& { return p.wind.on; }), "simulation.wind", true),
          breeze_if_calm), "wind (W)"),
      in_files_at(enum_field(setting("wind-model", "wind model",
          "aerodynamic, or the course's W-key force",
          no_range, 0.0, Cost::terms, applied_only, shared, allowed),
          wind_model_choices, [](auto& p) -> auto& { return p.wind.model; }),
          "simulation.wind.model"),
      offered_when(shown_as(as_speed_and_heading(in_the_panel(needed(in_files_at(vector_field(
          setting("wind-velocity", "wind velocity", "The air's velocity in m/s",
          limits::speed, 0.0, Cost::terms, in_panel, shared, allowed),
          [](auto& p) -> auto& { return p.wind.velocity; }), "simulation.wind.velocity")),
          {0.0, 30.0, ""}, "%.1f")), "wind"), aerodynamic_wind),
      in_files_at(number_field(setting("wind-drag", "wind drag", "The wind's drag coefficient C_d",
          limits::aerodynamic_coefficient, d.wind.drag, Cost::terms, applied_only, shared, allowed),
          SettingType::number, [](auto& p) -> auto& { return p.wind.drag; }),
          "simulation.wind.drag"),
      in_files_at(number_field(setting("wind-lift", "wind lift", "The wind's lift coefficient C_l",
          limits::aerodynamic_coefficient, d.wind.lift, Cost::terms, applied_only, shared, allowed),
          SettingType::number, [](auto& p) -> auto& { return p.wind.lift; }),
          "simulation.wind.lift"),
      in_files_at(number_field(setting("wind-gusts", "gusts",
          "The wind's relative gust strength, 0 steady",
          limits::gust_strength, d.wind.gusts, Cost::terms, applied_only, shared, allowed),
          SettingType::number, [](auto& p) -> auto& { return p.wind.gusts; }),
          "simulation.wind.gusts"),
      in_files_at(number_field(setting("air-density", "air density", "The air's density in kg/m³",
          limits::air_density, d.wind.air_density, Cost::terms, applied_only, shared, allowed),
          SettingType::number, [](auto& p) -> auto& { return p.wind.air_density; }),
          "simulation.wind.air_density"),
      // The panel drags its strength; the scene's direction stays, sideways part included.
      shown_as(as_strength(in_the_panel(pointing(in_files_at(vector_field(setting("gravity",
          "gravity", "Gravity in m/s² (a force in N, see gravity-model)",
          limits::acceleration, 0.0, Cost::gravity, in_panel, shared, allowed),
          [](auto& p) -> auto& { return p.gravity; }), "simulation.gravity"),
          Eigen::Vector3d(0.0, -1.0, 0.0)), {0.0, 30.0, ""}, "%.2f")), "gravity", "m/s^2"),
      enum_field(setting("gravity-model", "gravity model",
          "acceleration (f = m g) or force_per_vertex (f = g, the course's)",
          no_range, 0.0, Cost::gravity, in_scene, shared, allowed),
          gravity_model_choices, [](auto& p) -> auto& { return p.gravity_model; }),
      enum_field(setting("first-iterate", "first iterate",
          "Where each step's iterations start: current_positions or inertial_prediction",
          no_range, 0.0, Cost::value, in_scene, own, allowed),
          first_iterate_choices, [](auto& p) -> auto& { return p.first_iterate; }),
      section_switch(toggle_field(setting("self-collision", "self-collision",
          "Keep the surface from passing through itself (thickness: the scene's, else 0.01 m; "
          "not for course scenes)",
          no_range, 0.0, Cost::terms, everywhere_but_files, shared, refused),
          [](auto& p) -> auto& { return p.self_collision.on; }), "self_collision", false),
      shown_beside(shown_as(in_the_panel(implying(in_files_at(logarithmic(number_field(
          setting("self-collision-thickness",
          "thickness", "Self-collision thickness in m, 1e-5 to 1; implies --self-collision",
          limits::self_collision_thickness, d.self_collision.thickness, Cost::terms,
          everywhere_but_files, shared, refused),
          SettingType::number, [](auto& p) -> auto& { return p.self_collision.thickness; })),
          "self_collision.thickness"), "self-collision"), {0.01, 1000.0, ""}, "%.2f"),
          "thickness", "mm", 1000.0), "self-collision"),
  };
  // clang-format on
}

}  // namespace

const std::vector<SettingSpec>& built_in_settings() {
  static const std::vector<SettingSpec> settings = declare_built_in_settings();
  return settings;
}

}  // namespace wobble

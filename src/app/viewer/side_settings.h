#ifndef WOBBLE_APP_VIEWER_SIDE_SETTINGS_H
#define WOBBLE_APP_VIEWER_SIDE_SETTINGS_H

#include "sim/simulation_params.h"
#include "ui/panel_sections.h"

namespace wobble {

// The one translation between the panel's controls (ui/panel_sections.h) and the simulation's
// settings value, for the left side, the split view's right side and the environment alike: a
// control for each setting declared for the panel (sim/settings/setting_registry.h) that each
// side has its own of (k, dt, iterations, the solver, Chebyshev, and every added setting), or that
// the sides share (damping, friction, the wind, self-collision). No GL.

// Which settings a list of controls shows.
enum class PanelPart { each_side, environment };

// The controls showing `params`, one per such setting, in their order, each in the panel's unit
// and view (a thickness in mm, the wind's velocity as a speed and heading); a setting for solids
// alone is hidden unless `solid` (the scene's network has tetrahedra), and one the declaration
// does not offer for `params` (friction without colliders) is hidden.
void show_settings(const SimulationParams& params, SideSliders& sliders, bool solid = false,
                   PanelPart part = PanelPart::each_side);

// `params` with the controls' values in place of its own, ready for Simulation::apply. A value
// whose float the control still shows is kept as it is (the control holds 1/60 s as the float
// nearest it, which must not change dt); iterations are lowered to `most_iterations` (the mesh's
// limit, Simulation::max_iterations_for_mesh), in the controls too; a number is clamped into its
// range (a float's rounding can fall just outside it). A switch turned on is turned on as a user
// turns it on (SettingSpec::when_turned_on: the wind over a calm scene blows the breeze).
SimulationParams settings_from_sliders(const SimulationParams& params, SideSliders& sliders,
                                       int most_iterations);

}  // namespace wobble

#endif

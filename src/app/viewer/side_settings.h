#ifndef WOBBLE_APP_VIEWER_SIDE_SETTINGS_H
#define WOBBLE_APP_VIEWER_SIDE_SETTINGS_H

#include "sim/settings/simulation_params.h"
#include "ui/panel_sections.h"

namespace wobble {

// The one translation between a side's controls (ui/panel_sections.h) and the simulation's
// settings value, for the left side and the split view's right side alike: a control for each
// setting declared for the panel that each side has its own of (sim/settings/setting_registry.h:
// k, dt, iterations, the solver, Chebyshev, and every added setting). No GL.

// The controls showing `params`, one per such setting, in their order; a setting for solids
// alone is hidden unless `solid` (the scene's network has tetrahedra).
void show_settings(const SimulationParams& params, SideSliders& sliders, bool solid = false);

// `params` with the controls' values in place of its own, ready for Simulation::apply. A value
// whose float the control still shows is kept as it is (the control holds 1/60 s as the float
// nearest it, which must not change dt); iterations are lowered to `most_iterations` (the mesh's
// limit, Simulation::max_iterations_for_mesh), in the controls too; a number is clamped into its
// range (a float's rounding can fall just outside it).
SimulationParams settings_from_sliders(const SimulationParams& params, SideSliders& sliders,
                                       int most_iterations);

}  // namespace wobble

#endif

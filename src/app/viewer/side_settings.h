#ifndef WOBBLE_APP_VIEWER_SIDE_SETTINGS_H
#define WOBBLE_APP_VIEWER_SIDE_SETTINGS_H

#include "sim/simulation_params.h"
#include "ui/panel_sections.h"

namespace wobble {

// The one translation between a side's sliders (ui/panel_sections.h: k, dt, iterations, the
// solver, Chebyshev, and a slider per added setting) and the simulation's settings value, for the
// left side and the split view's right side alike. No GL.

// The sliders showing `params`: each built-in value, and one AddedSlider per added setting
// (sim/settings/setting_registry.h), in their order; a setting for solids alone is hidden unless
// `solid` (the scene's network has tetrahedra).
void show_settings(const SimulationParams& params, SideSliders& sliders, bool solid = false);

// `params` with the sliders' values in place of its own, ready for Simulation::apply. A value
// whose float the slider still shows is kept as it is (the slider holds 1/60 s as the float
// nearest it, which must not change dt); iterations are lowered to `most_iterations` (the mesh's
// limit, Simulation::max_iterations_for_mesh), in the sliders too; an added setting's slider is
// clamped into its range (a float's rounding can fall just outside it).
SimulationParams settings_from_sliders(const SimulationParams& params, SideSliders& sliders,
                                       int most_iterations);

}  // namespace wobble

#endif

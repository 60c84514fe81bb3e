#ifndef WOBBLE_UI_PANEL_STATS_H
#define WOBBLE_UI_PANEL_STATS_H

#include "control_panel.h"

namespace wobble {

// The panel's stats in a few short lines, each one line of text at the panel's width: frame
// rate and real time, the step's time, the simulated time, the shape's size and the solver
// stepping it. The panel pins them under its scrolling sections, so they stay in view. Between
// ImGui::Begin and End.
void draw_panel_stats(const PanelStats& stats, bool paused);

// How many lines draw_panel_stats draws for `stats`.
int panel_stats_lines(const PanelStats& stats);

// The step's time split into its parts (local, global, wind, plots, contact, self-collision),
// one a row: the panel's "timings" section. Nothing when the timings are hidden.
void draw_panel_timings(const PanelStats& stats);

}  // namespace wobble

#endif

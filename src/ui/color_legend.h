#ifndef WOBBLE_UI_COLOR_LEGEND_H
#define WOBBLE_UI_COLOR_LEGEND_H

#include <string>
#include <vector>

namespace wobble {

// A colour bar for the quantity the shape is coloured by, with its name and range, e.g.
//   strain                      speed (m/s)
//   [blue ... white ... red]    [dark ....... bright]
//   -2.1%      0      +2.1%     0               3.4
//   compression blue, stretch red
struct ColorLegend {
  std::string title;              // the quantity and its unit
  std::string low, middle, high;  // labels under the bar's left end, centre and right end
  std::string note;               // a line under the labels (what the colours mean), or empty
  std::vector<float> colors;      // n by 3 linear RGB samples of the map, left to right, n ≥ 2
};

// What else is on screen that the legend keeps clear of.
struct LegendClearance {
  // The plot windows' column at the right (instrument_windows.h): its left edge, negative when
  // no plot is open.
  float instrument_column_left = -1.0f;
  bool side_labels = false;  // the split view's labels along the bottom (side_labels.h)
};

// Draws the legend in a small undecorated window at the bottom right of the view: of the display,
// or left of the plot windows' column, and above the split view's labels; the panel is at the top
// left. Call between ImGui::NewFrame and ImGui::Render. `ui_scale` is the high-DPI factor.
void draw_color_legend(const ColorLegend& legend, float ui_scale,
                       const LegendClearance& clearance = LegendClearance());

}  // namespace wobble

#endif

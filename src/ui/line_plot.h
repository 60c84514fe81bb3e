#ifndef WOBBLE_UI_LINE_PLOT_H
#define WOBBLE_UI_LINE_PLOT_H

#include <imgui.h>

#include <vector>

namespace wobble {

// One curve of a line plot: count points (x[i], y[i]).
struct PlotSeries {
  const char* name = "";
  const double* x = nullptr;
  const double* y = nullptr;
  int count = 0;
  ImU32 color = IM_COL32(255, 255, 255, 255);
};

struct PlotAxes {
  bool log_y = false;           // decades on y; points with y ≤ 0 are left out
  const char* x_label = "";     // under the plot, e.g. "iteration"
  const char* y_label = "";     // top left, e.g. "‖∇‖ (N)"
  const char* x_format = "%g";  // tick labels
};

// A line plot drawn with ImGui's draw list (Dear ImGui 1.86 has no plot of several curves or
// log axes): a legend of the curves' names in rows above the plot, so it never covers a curve,
// then a frame, grid lines with labels (decades on a log axis, 4–6 round values on a linear
// one) and the curves. Takes `size` (pixels; 0 width: the window's) of the current window's
// layout.
void line_plot(const char* id, const std::vector<PlotSeries>& series, const PlotAxes& axes,
               ImVec2 size);

// Where line_plot puts its parts, in screen pixels, for a plot at `origin` of `size` with text
// `line` pixels high whose named curves' names are `name_widths` pixels wide.
struct PlotLayout {
  ImVec2 area_min, area_max;  // the curves' frame
  // Each name's legend entry: a swatch of its colour (a line wide) then its name, starting at
  // legend[i], one line high and legend_width(name_widths[i], line) wide; in rows from the top
  // left, as many a row as fit in `size`.
  std::vector<ImVec2> legend;
};
PlotLayout plot_layout(ImVec2 origin, ImVec2 size, float line,
                       const std::vector<float>& name_widths);
float legend_width(float name_width, float line);

// Round tick values for a linear axis from lower to upper: 4 to 10 multiples of 1, 2 or 5 × 10ⁿ.
std::vector<double> linear_ticks(double lower, double upper);

}  // namespace wobble

#endif

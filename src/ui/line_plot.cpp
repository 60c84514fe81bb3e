#include "line_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace wobble {

std::vector<double> linear_ticks(double lower, double upper) {
  std::vector<double> ticks;
  if (!(upper > lower) || !std::isfinite(upper - lower)) return ticks;
  const double raw = (upper - lower) / 5.0;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  double step = decade;
  for (const double factor : {1.0, 2.0, 5.0, 10.0}) {
    step = factor * decade;
    if ((upper - lower) / step <= 6.0) break;
  }
  for (double tick = std::ceil(lower / step) * step; tick <= upper + 1e-9 * step; tick += step) {
    ticks.push_back(std::abs(tick) < 1e-12 * step ? 0.0 : tick);
  }
  return ticks;
}

namespace {

struct Range {
  double lower = std::numeric_limits<double>::infinity();
  double upper = -std::numeric_limits<double>::infinity();
  void add(double v) {
    lower = std::min(lower, v);
    upper = std::max(upper, v);
  }
  bool empty() const { return !(upper >= lower); }
};

}  // namespace

float legend_width(float name_width, float line) {
  return 1.4f * line + name_width;
}

PlotLayout plot_layout(ImVec2 origin, ImVec2 size, float line,
                       const std::vector<float>& name_widths) {
  PlotLayout layout;
  // Entries flow left to right over the whole width, a line apart, and wrap.
  const float left = origin.x + 4.5f * line, right = origin.x + size.x - 0.5f * line;
  ImVec2 at = origin;
  for (const float width : name_widths) {
    const float entry = legend_width(width, line);
    if (at.x > origin.x && at.x + entry > right) at = ImVec2(origin.x, at.y + line);
    layout.legend.push_back(at);
    at.x += entry + line;
  }
  const float legend_height = name_widths.empty() ? 0.0f : at.y + line - origin.y;
  // Under the legend, a line for the y axis's label; under the plot, the x axis's ticks and
  // label; at the left, the y axis's ticks.
  layout.area_min = ImVec2(left, origin.y + legend_height + 1.2f * line);
  layout.area_max = ImVec2(right, origin.y + size.y - 2.2f * line);
  return layout;
}

void line_plot(const char* id, const std::vector<PlotSeries>& series, const PlotAxes& axes,
               ImVec2 size) {
  ImGui::PushID(id);
  if (size.x <= 0.0f) size.x = ImGui::GetContentRegionAvail().x;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::Dummy(size);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float line = ImGui::GetTextLineHeight();
  std::vector<const PlotSeries*> named;
  std::vector<float> name_widths;
  for (const PlotSeries& s : series) {
    if (s.name == nullptr || s.name[0] == '\0') continue;
    named.push_back(&s);
    name_widths.push_back(ImGui::CalcTextSize(s.name).x);
  }
  const PlotLayout layout = plot_layout(origin, size, line, name_widths);
  for (std::size_t i = 0; i < named.size(); ++i) {
    const ImVec2 at = layout.legend[i];
    draw->AddRectFilled(ImVec2(at.x, at.y + 0.45f * line), ImVec2(at.x + line, at.y + 0.6f * line),
                        named[i]->color);
    draw->AddText(ImVec2(at.x + 1.4f * line, at.y), named[i]->color, named[i]->name);
  }
  const ImVec2 top_left = layout.area_min, bottom_right = layout.area_max;
  draw->AddRectFilled(top_left, bottom_right, IM_COL32(20, 22, 26, 255));
  draw->AddRect(top_left, bottom_right, IM_COL32(90, 90, 100, 255));

  Range xs, ys;
  for (const PlotSeries& s : series) {
    for (int i = 0; i < s.count; ++i) {
      if (!std::isfinite(s.y[i]) || !std::isfinite(s.x[i])) continue;
      if (axes.log_y && !(s.y[i] > 0.0)) continue;
      xs.add(s.x[i]);
      ys.add(axes.log_y ? std::log10(s.y[i]) : s.y[i]);
    }
  }
  const ImU32 label_color = ImGui::GetColorU32(ImGuiCol_TextDisabled);
  draw->AddText(ImVec2(top_left.x, top_left.y - 1.2f * line), label_color, axes.y_label);
  draw->AddText(
      ImVec2(0.5f * (top_left.x + bottom_right.x) - 2.0f * line, bottom_right.y + 1.1f * line),
      label_color, axes.x_label);
  if (xs.empty() || ys.empty()) {
    ImGui::PopID();
    return;
  }
  if (axes.log_y) {
    ys.lower = std::floor(ys.lower);
    ys.upper = std::max(std::ceil(ys.upper), ys.lower + 1.0);
  } else if (ys.upper - ys.lower < 1e-12 * std::max(1.0, std::abs(ys.upper))) {
    ys.lower -= 0.5;
    ys.upper += 0.5;
  } else {
    const double pad = 0.05 * (ys.upper - ys.lower);
    ys.lower -= pad;
    ys.upper += pad;
  }
  if (xs.upper <= xs.lower) xs.upper = xs.lower + 1.0;
  const auto to_screen = [&](double x, double y) {
    const double u = (x - xs.lower) / (xs.upper - xs.lower);
    const double v = (y - ys.lower) / (ys.upper - ys.lower);
    return ImVec2(top_left.x + static_cast<float>(u) * (bottom_right.x - top_left.x),
                  bottom_right.y - static_cast<float>(v) * (bottom_right.y - top_left.y));
  };

  char text[32];
  const ImU32 grid_color = IM_COL32(60, 62, 70, 255);
  if (axes.log_y) {
    // One line a decade; labels on every decade, or every other when they would crowd.
    const int decades = static_cast<int>(ys.upper - ys.lower);
    const int label_every = decades > 6 ? (decades + 5) / 6 : 1;
    for (int d = static_cast<int>(ys.lower); d <= static_cast<int>(ys.upper); ++d) {
      const ImVec2 a = to_screen(xs.lower, d), b = to_screen(xs.upper, d);
      draw->AddLine(a, b, grid_color);
      if ((d - static_cast<int>(ys.lower)) % label_every != 0) continue;
      std::snprintf(text, sizeof(text), "1e%d", d);
      draw->AddText(ImVec2(origin.x, a.y - 0.5f * line), label_color, text);
    }
  } else {
    for (const double tick : linear_ticks(ys.lower, ys.upper)) {
      const ImVec2 a = to_screen(xs.lower, tick), b = to_screen(xs.upper, tick);
      draw->AddLine(a, b, grid_color);
      std::snprintf(text, sizeof(text), "%.3g", tick);
      draw->AddText(ImVec2(origin.x, a.y - 0.5f * line), label_color, text);
    }
  }
  for (const double tick : linear_ticks(xs.lower, xs.upper)) {
    const ImVec2 a = to_screen(tick, ys.lower);
    draw->AddLine(a, to_screen(tick, ys.upper), grid_color);
    std::snprintf(text, sizeof(text), axes.x_format, tick);
    draw->AddText(ImVec2(a.x - 0.5f * ImGui::CalcTextSize(text).x, bottom_right.y + 0.1f * line),
                  label_color, text);
  }

  draw->PushClipRect(top_left, bottom_right, true);
  std::vector<ImVec2> points;
  for (const PlotSeries& s : series) {
    points.clear();
    for (int i = 0; i < s.count; ++i) {
      const bool drawable =
          std::isfinite(s.y[i]) && std::isfinite(s.x[i]) && (!axes.log_y || s.y[i] > 0.0);
      // A gap (a zero on a log axis) ends the polyline; the next point starts another.
      if (!drawable) {
        if (points.size() > 1)
          draw->AddPolyline(points.data(), static_cast<int>(points.size()), s.color,
                            ImDrawFlags_None, 2.0f);
        points.clear();
        continue;
      }
      points.push_back(to_screen(s.x[i], axes.log_y ? std::log10(s.y[i]) : s.y[i]));
    }
    if (points.size() > 1) {
      draw->AddPolyline(points.data(), static_cast<int>(points.size()), s.color, ImDrawFlags_None,
                        2.0f);
    } else if (points.size() == 1) {
      draw->AddCircleFilled(points[0], 2.5f, s.color);
    }
  }
  draw->PopClipRect();

  ImGui::PopID();
}

}  // namespace wobble

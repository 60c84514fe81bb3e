#include "instrument_windows.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "line_plot.h"

namespace wobble {

namespace {

ImVec4 light_color(ConvergenceLight light) {
  switch (light) {
    case ConvergenceLight::green:
      return ImVec4(0.35f, 0.85f, 0.35f, 1.0f);
    case ConvergenceLight::amber:
      return ImVec4(1.0f, 0.72f, 0.15f, 1.0f);
    case ConvergenceLight::red:
      return ImVec4(1.0f, 0.3f, 0.25f, 1.0f);
  }
  return ImVec4(1, 1, 1, 1);
}

// Below this share of the energy, a difference between two iterates' energies is rounding.
constexpr double rounding_share = 1e-12;

std::vector<double> iteration_numbers(std::size_t count) {
  std::vector<double> x(count);
  for (std::size_t i = 0; i < count; ++i)
    x[i] = static_cast<double>(i);
  return x;
}

bool has_step(const ConvergenceCurve& side) {
  return side.energy != nullptr && !side.energy->empty() && side.gradient_norm != nullptr;
}

int iterations_of(const ConvergenceCurve& side) {
  return static_cast<int>(side.energy->size()) - 1;
}

// A side's light: a disc of its colour, then its words and how far the gradient fell (its last
// over the step's scale, ConvergenceTrace::gradient_reduction), after `name` ("left: ", or
// nothing when there is one side).
void draw_light(const ConvergenceCurve& side, const char* name) {
  const ImVec4 color = light_color(side.light);
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const float line = ImGui::GetTextLineHeight();
  ImGui::GetWindowDrawList()->AddCircleFilled(ImVec2(at.x + 0.5f * line, at.y + 0.5f * line),
                                              0.45f * line, ImGui::GetColorU32(color));
  ImGui::Dummy(ImVec2(line, line));
  ImGui::SameLine();
  // Two sides' lines carry their names: " of scale" would no longer fit the column.
  // Wrapped, in the light's colour: a narrow column (a projector's UI scale) keeps it whole.
  ImGui::PushStyleColor(ImGuiCol_Text, color);
  ImGui::TextWrapped("%s%s: |grad| at %.2g%s", name, convergence_label(side.light), side.reduction,
                     name[0] == '\0' ? " of scale" : "");
  ImGui::PopStyleColor();
}

}  // namespace

std::string legend_number(double value, double scale) {
  // Four significant digits of the scale, and the same decimals for every value read against it.
  const double magnitude =
      std::abs(scale) > 0.0 && std::isfinite(scale) ? std::floor(std::log10(std::abs(scale))) : 0.0;
  const int decimals = static_cast<int>(std::clamp(3.0 - magnitude, 0.0, 9.0));
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", decimals, value);
  return text;
}

const char* convergence_label(ConvergenceLight light) {
  switch (light) {
    case ConvergenceLight::green:
      return "converged";
    case ConvergenceLight::amber:
      return "partly converged";
    case ConvergenceLight::red:
      return "far from converged";
  }
  return "";
}

float instrument_column_width(float display_width, float ui_scale, float panel_right) {
  const float width = std::min(380.0f * ui_scale, 0.45f * display_width);
  if (!(panel_right > 0.0f)) return width;
  // What the panel and the column leave the shape, with the column's margin from the edge.
  const float leaving =
      display_width - column_free_share * display_width - 10.0f * ui_scale - panel_right;
  return std::min(width, std::max(leaving, std::min(width, min_column_width * ui_scale)));
}

float instrument_column_left(float display_width, float ui_scale, float panel_right) {
  return display_width - instrument_column_width(display_width, ui_scale, panel_right) -
         10.0f * ui_scale;
}

const char* convergence_hint(ConvergenceLight light, bool chebyshev_applies) {
  // Only far from converged: amber is a step that got most of the way, nothing to fix.
  if (light != ConvergenceLight::red) return "";
  return chebyshev_applies ? "stiff springs need more iterations, Chebyshev, or a smaller dt"
                           : "stiff springs need more iterations or a smaller dt";
}

void draw_convergence_window(const ConvergencePlotData& data, bool& open, float ui_scale,
                             float panel_right) {
  // Top right, out of the way of the panel (top left) and of a shape framed in the middle; on a
  // small display (a headless image) the two windows share the right side's height.
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float width = instrument_column_width(display.x, ui_scale, panel_right);
  ImGui::SetNextWindowPos(
      ImVec2(instrument_column_left(display.x, ui_scale, panel_right), 10.0f * ui_scale),
      ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(width, std::min(390.0f * ui_scale, 0.6f * display.y - 15.0f)),
                           ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Convergence of the last step", &open)) {
    ImGui::End();
    return;
  }
  // The sides that took a step: the left one alone, or both sides of a split view.
  std::vector<const ConvergenceCurve*> sides;
  if (has_step(data.left)) sides.push_back(&data.left);
  if (data.right && has_step(*data.right)) sides.push_back(&*data.right);
  if (sides.empty()) {
    ImGui::TextDisabled("no step taken yet");
    ImGui::End();
    return;
  }
  const bool split = data.right.has_value();
  // The worst light's hint, once; Chebyshev suggested only if every side that needs it can.
  const ConvergenceCurve* worst = nullptr;
  bool chebyshev_applies = true;
  for (const ConvergenceCurve* side : sides) {
    if (side->light == ConvergenceLight::green) continue;
    if (!worst || side->light > worst->light) worst = side;
    chebyshev_applies = chebyshev_applies && side->chebyshev_applies;
  }
  for (const ConvergenceCurve* side : sides) {
    const char* name = !split ? "" : side == &data.left ? "left: " : "right: ";
    draw_light(*side, name);
  }
  if (worst && worst->light == ConvergenceLight::red) {
    ImGui::PushStyleColor(ImGuiCol_Text, light_color(worst->light));
    ImGui::TextWrapped("%s", convergence_hint(worst->light, chebyshev_applies));
    ImGui::PopStyleColor();
  }
  if (!split) {
    ImGui::Text("step %ld, %d %s iterations", data.left.step, iterations_of(data.left),
                data.left.method.c_str());
  } else if (sides.size() == 2 && sides[0]->step == sides[1]->step) {
    ImGui::TextWrapped("step %ld, %d iterations left, %d right", sides[0]->step,
                       iterations_of(*sides[0]), iterations_of(*sides[1]));
  } else {
    // Different dt: the sides count their own steps.
    std::string steps;
    for (const ConvergenceCurve* side : sides) {
      char text[96];
      std::snprintf(text, sizeof(text), "%s%s: step %ld, %d iterations", steps.empty() ? "" : "; ",
                    side == &data.left ? "left" : "right", side->step, iterations_of(*side));
      steps += text;
    }
    ImGui::TextWrapped("%s", steps.c_str());
  }

  // One curve a side on each plot, the left side's in blue and the right side's in orange; alone,
  // the gradient in blue and the energy in orange.
  const ImU32 blue = IM_COL32(110, 190, 255, 255), orange = IM_COL32(255, 170, 90, 255);
  std::vector<std::vector<double>> x(sides.size()), above(sides.size());
  std::vector<std::string> gradient_names(sides.size()), energy_names(sides.size());
  std::vector<PlotSeries> gradient_series, energy_series;
  for (std::size_t s = 0; s < sides.size(); ++s) {
    const ConvergenceCurve& side = *sides[s];
    const std::vector<double>& energy = *side.energy;
    x[s] = iteration_numbers(energy.size());
    // The objective's own value is offset by −pᵀf_ext; what shows convergence is how far each
    // iterate's energy is above the lowest reached.
    // Differences below about 1e-12 of the energy itself are its rounding, not convergence (a
    // step at rest drew broken noise near 1e-14): they are left out, as the lowest itself (0 on
    // a log axis) always was, so the curve ends where the energy stops changing.
    const double lowest = *std::min_element(energy.begin(), energy.end());
    const double floor = rounding_share * std::max(std::abs(lowest), std::abs(energy[0]));
    above[s].resize(energy.size());
    for (std::size_t i = 0; i < energy.size(); ++i) {
      const double difference = energy[i] - lowest;
      above[s][i] = difference > floor ? difference : 0.0;
    }
    const char* name = !split ? "" : sides[s] == &data.left ? "left: " : "right: ";
    gradient_names[s] = name + side.solver;
    char e0[64];
    std::snprintf(e0, sizeof(e0), "%sE0 = %.6g J", split ? name : "", energy.front());
    energy_names[s] = e0;
    const bool right = sides[s] != &data.left;
    const int count = static_cast<int>(energy.size());
    gradient_series.push_back({gradient_names[s].c_str(), x[s].data(), side.gradient_norm->data(),
                               count, split && right ? orange : blue});
    energy_series.push_back({energy_names[s].c_str(), x[s].data(), above[s].data(), count,
                             split && !right ? blue : orange});
  }

  const float line = ImGui::GetTextLineHeight();
  const float plot_height = 0.5f * (ImGui::GetContentRegionAvail().y - 0.5f * line);
  PlotAxes axes;
  axes.log_y = true;
  axes.x_label = "iteration";
  axes.y_label = "|grad E| (N)";
  axes.x_format = "%.0f";
  line_plot("gradient", gradient_series, axes, ImVec2(0.0f, plot_height));
  axes.y_label = "E - lowest E (J)";
  line_plot("energy", energy_series, axes, ImVec2(0.0f, plot_height));
  ImGui::End();
}

void draw_energy_window(const EnergyPlotData& data, bool& open, float ui_scale, float panel_right) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float width = instrument_column_width(display.x, ui_scale, panel_right);
  const float top = std::min(410.0f * ui_scale, 0.6f * display.y + 5.0f);
  ImGui::SetNextWindowPos(ImVec2(instrument_column_left(display.x, ui_scale, panel_right), top),
                          ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(width, std::min(250.0f * ui_scale, display.y - top - 10.0f)),
                           ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Energy over time", &open)) {
    ImGui::End();
    return;
  }
  if (data.time == nullptr || data.time->empty()) {
    ImGui::TextDisabled("no step taken yet");
    ImGui::End();
    return;
  }
  const int count = static_cast<int>(data.time->size());
  PlotAxes axes;
  axes.x_label = "time (s)";
  if (data.right_time != nullptr) {
    // Split: the two sides' totals, in the convergence window's colours for left and right; how
    // the methods lose energy is the comparison (the breakdown is the single view's).
    axes.y_label = "total J";
    const bool right_stepped = !data.right_time->empty();
    const double scale = std::max(std::abs(data.total->back()),
                                  right_stepped ? std::abs(data.right_total->back()) : 0.0);
    const std::string left =
        "left, " + data.left_solver + ": " + legend_number(data.total->back(), scale) + " J";
    std::string right;
    std::vector<PlotSeries> series = {
        {left.c_str(), data.time->data(), data.total->data(), count, IM_COL32(110, 190, 255, 255)}};
    if (right_stepped) {
      right = "right, " + data.right_solver + ": " +
              legend_number(data.right_total->back(), scale) + " J";
      series.push_back({right.c_str(), data.right_time->data(), data.right_total->data(),
                        static_cast<int>(data.right_time->size()), IM_COL32(255, 170, 90, 255)});
    }
    line_plot("energy", series, axes, ImVec2(0.0f, ImGui::GetContentRegionAvail().y));
    ImGui::End();
    return;
  }
  // One number of decimals for all four, from the largest: the legend keeps its layout from
  // frame to frame (with %g each entry's digits came and went as the values moved).
  const double scale = std::max({std::abs(data.kinetic->back()), std::abs(data.spring->back()),
                                 std::abs(data.gravity->back()), std::abs(data.total->back())});
  const std::string kinetic = "kinetic " + legend_number(data.kinetic->back(), scale) + " J";
  const std::string spring = "spring " + legend_number(data.spring->back(), scale) + " J";
  const std::string gravity = "gravity " + legend_number(data.gravity->back(), scale) + " J";
  const std::string total = "total " + legend_number(data.total->back(), scale) + " J";
  axes.y_label = "J";
  line_plot(
      "energy",
      {{kinetic.c_str(), data.time->data(), data.kinetic->data(), count,
        IM_COL32(255, 120, 90, 255)},
       {spring.c_str(), data.time->data(), data.spring->data(), count,
        IM_COL32(110, 210, 120, 255)},
       {gravity.c_str(), data.time->data(), data.gravity->data(), count,
        IM_COL32(110, 170, 255, 255)},
       {total.c_str(), data.time->data(), data.total->data(), count, IM_COL32(240, 240, 240, 255)}},
      axes, ImVec2(0.0f, ImGui::GetContentRegionAvail().y));
  ImGui::End();
}

}  // namespace wobble

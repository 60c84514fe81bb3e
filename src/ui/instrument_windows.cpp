#include "instrument_windows.h"

#include <imgui.h>

#include <algorithm>
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

std::vector<double> iteration_numbers(std::size_t count) {
  std::vector<double> x(count);
  for (std::size_t i = 0; i < count; ++i)
    x[i] = static_cast<double>(i);
  return x;
}

}  // namespace

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

float instrument_column_width(float display_width, float ui_scale) {
  return std::min(380.0f * ui_scale, 0.45f * display_width);
}

float instrument_column_left(float display_width, float ui_scale) {
  return display_width - instrument_column_width(display_width, ui_scale) - 10.0f * ui_scale;
}

const char* convergence_hint(ConvergenceLight light) {
  if (light == ConvergenceLight::green) return "";
  return "stiff springs need more iterations, Chebyshev, or a smaller dt";
}

void draw_convergence_window(const ConvergencePlotData& data, bool& open, float ui_scale) {
  // Top right, out of the way of the panel (top left) and of a shape framed in the middle; on a
  // small display (a headless image) the two windows share the right side's height.
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float width = instrument_column_width(display.x, ui_scale);
  ImGui::SetNextWindowPos(ImVec2(instrument_column_left(display.x, ui_scale), 10.0f * ui_scale),
                          ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(width, std::min(390.0f * ui_scale, 0.6f * display.y - 15.0f)),
                           ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Convergence of the last step", &open)) {
    ImGui::End();
    return;
  }
  if (data.energy == nullptr || data.energy->empty()) {
    ImGui::TextDisabled("no step taken yet");
    ImGui::End();
    return;
  }
  const std::vector<double>& energy = *data.energy;
  const std::vector<double>& gradient = *data.gradient_norm;
  const int iterations = static_cast<int>(energy.size()) - 1;

  const ImVec4 color = light_color(data.light);
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const float line = ImGui::GetTextLineHeight();
  ImGui::GetWindowDrawList()->AddCircleFilled(ImVec2(at.x + 0.5f * line, at.y + 0.5f * line),
                                              0.45f * line, ImGui::GetColorU32(color));
  ImGui::Dummy(ImVec2(line, line));
  ImGui::SameLine();
  ImGui::TextColored(color, "%s: |grad| at %.2g of start", convergence_label(data.light),
                     data.reduction);
  const char* hint = convergence_hint(data.light);
  if (hint[0] != '\0') {
    ImGui::PushStyleColor(ImGuiCol_Text, color);
    ImGui::TextWrapped("%s", hint);
    ImGui::PopStyleColor();
  }
  ImGui::Text("step %ld, %d %s iterations", data.step, iterations,
              data.chebyshev ? "Chebyshev" : "plain");

  const std::vector<double> x = iteration_numbers(energy.size());
  // The objective's own value is offset by −pᵀf_ext; what shows convergence is how far each
  // iterate's energy is above the lowest reached.
  const double lowest = *std::min_element(energy.begin(), energy.end());
  std::vector<double> above(energy.size());
  for (std::size_t i = 0; i < energy.size(); ++i)
    above[i] = energy[i] - lowest;

  const float plot_height = 0.5f * (ImGui::GetContentRegionAvail().y - 0.5f * line);
  PlotAxes axes;
  axes.log_y = true;
  axes.x_label = "iteration";
  axes.y_label = "|grad E| (N)";
  axes.x_format = "%.0f";
  line_plot("gradient",
            {{data.chebyshev ? "Chebyshev" : "plain", x.data(), gradient.data(),
              static_cast<int>(gradient.size()), IM_COL32(110, 190, 255, 255)}},
            axes, ImVec2(0.0f, plot_height));
  axes.y_label = "E - lowest E (J)";
  char name[64];
  std::snprintf(name, sizeof(name), "E0 = %.6g J", energy.front());
  line_plot(
      "energy",
      {{name, x.data(), above.data(), static_cast<int>(above.size()), IM_COL32(255, 170, 90, 255)}},
      axes, ImVec2(0.0f, plot_height));
  ImGui::End();
}

void draw_energy_window(const EnergyPlotData& data, bool& open, float ui_scale) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float width = instrument_column_width(display.x, ui_scale);
  const float top = std::min(410.0f * ui_scale, 0.6f * display.y + 5.0f);
  ImGui::SetNextWindowPos(ImVec2(instrument_column_left(display.x, ui_scale), top),
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
  char kinetic[48], spring[48], gravity[48], total[48];
  std::snprintf(kinetic, sizeof(kinetic), "kinetic %.4g J", data.kinetic->back());
  std::snprintf(spring, sizeof(spring), "spring %.4g J", data.spring->back());
  std::snprintf(gravity, sizeof(gravity), "gravity %.4g J", data.gravity->back());
  std::snprintf(total, sizeof(total), "total %.4g J", data.total->back());
  PlotAxes axes;
  axes.x_label = "time (s)";
  axes.y_label = "J";
  line_plot(
      "energy",
      {{kinetic, data.time->data(), data.kinetic->data(), count, IM_COL32(255, 120, 90, 255)},
       {spring, data.time->data(), data.spring->data(), count, IM_COL32(110, 210, 120, 255)},
       {gravity, data.time->data(), data.gravity->data(), count, IM_COL32(110, 170, 255, 255)},
       {total, data.time->data(), data.total->data(), count, IM_COL32(240, 240, 240, 255)}},
      axes, ImVec2(0.0f, ImGui::GetContentRegionAvail().y));
  ImGui::End();
}

}  // namespace wobble

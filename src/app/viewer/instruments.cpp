// The viewer's classroom instruments: the convergence of the last step and the energy over time,
// recorded only while their windows are open (or a CSV asks for them).
#include "app/viewer/instruments.h"

#include <imgui.h>

#include <algorithm>
#include <charconv>

#include "app/cli/solver_choice.h"
#include "app/outputs/instrument_csv.h"
#include "ui/instrument_windows.h"

namespace wobble {

namespace {

// How much of the past the energy plot shows (s of simulated time).
constexpr double energy_history_seconds = 10.0;

ConvergenceLight light_for(const ConvergenceTrace& trace) {
  switch (classify(trace)) {
    case Convergence::converged:
      return ConvergenceLight::green;
    case Convergence::partial:
      return ConvergenceLight::amber;
    case Convergence::far:
      return ConvergenceLight::red;
  }
  return ConvergenceLight::red;
}

// A side's last step as the convergence window shows it, named by the solver that took it.
ConvergenceCurve curve_of(const ConvergenceTrace& trace, long step) {
  ConvergenceCurve curve;
  curve.energy = &trace.energy;
  curve.gradient_norm = &trace.gradient_norm;
  curve.solver = solver_label(trace.solver, trace.chebyshev);
  const bool local_global = solver_takes_chebyshev(trace.solver);
  curve.method = !local_global     ? solver_label(trace.solver)
                 : trace.chebyshev ? "Chebyshev"
                                   : "plain";
  // Chebyshev is suggested only where it would change something: local-global without it.
  curve.chebyshev_applies = local_global && !trace.chebyshev;
  curve.light = light_for(trace);
  curve.reduction = trace.gradient_reduction();
  curve.step = step;
  return curve;
}

}  // namespace

void EnergyHistory::clear() {
  for (std::vector<double>* series : {&time, &kinetic, &spring, &gravity, &total})
    series->clear();
}

void EnergyHistory::add(double at, const FrameEnergy& energy) {
  // Older samples leave in blocks, so that trimming costs little per step.
  if (!time.empty() && at - time.front() > 1.25 * energy_history_seconds) {
    const auto keep_from = std::lower_bound(time.begin(), time.end(), at - energy_history_seconds);
    const auto drop = keep_from - time.begin();
    for (std::vector<double>* series : {&time, &kinetic, &spring, &gravity, &total})
      series->erase(series->begin(), series->begin() + drop);
  }
  time.push_back(at);
  kinetic.push_back(energy.kinetic);
  spring.push_back(energy.spring);
  gravity.push_back(energy.gravity);
  total.push_back(energy.total);
}

void Instruments::Shown::take(ConvergenceTrace& taken, long step,
                              const std::vector<std::pair<double, FrameEnergy>>& samples) {
  if (step > 0) {
    std::swap(trace, taken);
    trace_step = step;
  }
  for (const auto& [time, sample] : samples)
    energy.add(time, sample);
}

void Instruments::Shown::clear() {
  trace = ConvergenceTrace();
  trace_step = 0;
  energy.clear();
}

std::string Instruments::convergence_csv() const {
  if (left_.trace_step == 0 || left_.trace.energy.empty()) return "";
  std::string text = convergence_csv_header;
  append_convergence_rows(text, left_.trace_step, left_.trace);
  return text;
}

std::string Instruments::energy_csv() const {
  std::string text = "time,kinetic,spring,gravity,total\n";
  const EnergyHistory& shown = left_.energy;
  for (std::size_t i = 0; i < shown.time.size(); ++i) {
    char time[32];
    const auto end = std::to_chars(time, time + sizeof(time), shown.time[i]).ptr;
    text.append(time, end);
    append_csv_value(text, shown.kinetic[i]);
    append_csv_value(text, shown.spring[i]);
    append_csv_value(text, shown.gravity[i]);
    append_csv_value(text, shown.total[i]);
    text.push_back('\n');
  }
  return text;
}

void Instruments::clear() {
  left_.clear();
  right_.clear();
}

void Instruments::take(ConvergenceTrace& trace, long trace_step,
                       const std::vector<std::pair<double, FrameEnergy>>& energy) {
  left_.take(trace, trace_step, energy);
}

void Instruments::take_right(ConvergenceTrace& trace, long trace_step,
                             const std::vector<std::pair<double, FrameEnergy>>& energy) {
  right_.take(trace, trace_step, energy);
}

void Instruments::set_sides(PlottedSides sides) {
  if (!sides.split) right_.clear();
  sides_ = std::move(sides);
}

float Instruments::draw(float ui_scale, float panel_right) {
  bool& convergence_open = open_.show_convergence;
  bool& energy_open = open_.show_energy;
  // The plots stand in a column at the window's right (instrument_windows.h).
  const float display = ImGui::GetIO().DisplaySize.x;
  const float column_left = convergence_open || energy_open
                                ? instrument_column_left(display, ui_scale, panel_right)
                                : -1.0f;
  if (convergence_open) {
    ConvergencePlotData data;
    data.left = curve_of(left_.trace, left_.trace_step);
    if (sides_.split) data.right = curve_of(right_.trace, right_.trace_step);
    draw_convergence_window(data, convergence_open, ui_scale, panel_right);
  }
  if (energy_open) {
    EnergyPlotData data;
    const EnergyHistory& left = left_.energy;
    data.time = &left.time;
    data.kinetic = &left.kinetic;
    data.spring = &left.spring;
    data.gravity = &left.gravity;
    data.total = &left.total;
    if (sides_.split) {
      data.right_time = &right_.energy.time;
      data.right_total = &right_.energy.total;
      data.left_solver = sides_.left_solver;
      data.right_solver = sides_.right_solver;
    }
    draw_energy_window(data, energy_open, ui_scale, panel_right);
  }
  // A window closed here stops its recording from the next batch on.
  if (!energy_open) {
    left_.energy.clear();
    right_.energy.clear();
  }
  return column_left;
}

}  // namespace wobble

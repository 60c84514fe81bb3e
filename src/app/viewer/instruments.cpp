// The viewer's classroom instruments: the convergence of the last step and the energy over time,
// recorded only while their windows are open (or a CSV asks for them).
#include "app/viewer/instruments.h"

#include <imgui.h>

#include <algorithm>

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

void Instruments::clear() {
  shown_trace_ = ConvergenceTrace();
  shown_trace_step_ = 0;
  energy_history_.clear();
}

void Instruments::take(ConvergenceTrace& trace, long trace_step,
                       const std::vector<std::pair<double, FrameEnergy>>& energy) {
  if (trace_step > 0) {
    std::swap(shown_trace_, trace);
    shown_trace_step_ = trace_step;
  }
  for (const auto& [time, sample] : energy)
    energy_history_.add(time, sample);
}

float Instruments::draw(float ui_scale) {
  bool& convergence_open = open_.show_convergence;
  bool& energy_open = open_.show_energy;
  // The plots stand in a column at the window's right (instrument_windows.h).
  const float display = ImGui::GetIO().DisplaySize.x;
  const float column_left =
      convergence_open || energy_open ? instrument_column_left(display, ui_scale) : -1.0f;
  if (convergence_open) {
    ConvergencePlotData data;
    data.energy = &shown_trace_.energy;
    data.gradient_norm = &shown_trace_.gradient_norm;
    data.chebyshev = shown_trace_.chebyshev;
    data.light = light_for(shown_trace_);
    data.reduction = shown_trace_.gradient_reduction();
    data.step = shown_trace_step_;
    draw_convergence_window(data, convergence_open, ui_scale);
  }
  if (energy_open) {
    EnergyPlotData data;
    data.time = &energy_history_.time;
    data.kinetic = &energy_history_.kinetic;
    data.spring = &energy_history_.spring;
    data.gravity = &energy_history_.gravity;
    data.total = &energy_history_.total;
    draw_energy_window(data, energy_open, ui_scale);
  }
  // A window closed here stops its recording from the next batch on.
  if (!energy_open) energy_history_.clear();
  return column_left;
}

}  // namespace wobble

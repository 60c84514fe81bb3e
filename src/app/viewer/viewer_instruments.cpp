// The viewer's classroom instruments: the convergence of the last step and the energy over time,
// recorded only while their windows are open (or a CSV asks for them).
#include <algorithm>

#include "app/viewer/viewer.h"
#include "sim/instruments/frame_energy.h"
#include "ui/instrument_windows.h"

#include <imgui.h>

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

void Viewer::set_convergence_required(bool required) {
  convergence_required_ = required;
  update_recording();
}

void Viewer::update_recording() {
  const bool on = convergence_required_ || panel_.show_convergence;
  if (simulation_->records_convergence() != on) simulation_->set_convergence_recording(on);
}

void Viewer::clear_instruments() {
  shown_trace_ = ConvergenceTrace();
  shown_trace_step_ = 0;
  energy_history_.clear();
}

void Viewer::show_instruments(float ui_scale) {
  // The plots stand in a column at the window's right (instrument_windows.h); a split view
  // keeps left of it.
  const float display = ImGui::GetIO().DisplaySize.x;
  instruments_left_ = panel_.show_convergence || panel_.show_energy
                          ? display - instrument_column_width(display, ui_scale) - 10.0f * ui_scale
                          : -1.0f;
  if (panel_.show_convergence) {
    ConvergencePlotData data;
    data.energy = &shown_trace_.energy;
    data.gradient_norm = &shown_trace_.gradient_norm;
    data.chebyshev = shown_trace_.chebyshev;
    data.light = light_for(shown_trace_);
    data.reduction = shown_trace_.gradient_reduction();
    data.step = shown_trace_step_;
    draw_convergence_window(data, panel_.show_convergence, ui_scale);
  }
  if (panel_.show_energy) {
    EnergyPlotData data;
    data.time = &energy_history_.time;
    data.kinetic = &energy_history_.kinetic;
    data.spring = &energy_history_.spring;
    data.gravity = &energy_history_.gravity;
    data.total = &energy_history_.total;
    draw_energy_window(data, panel_.show_energy, ui_scale);
  }
  // A window closed here stops its recording from the next batch on.
  if (!panel_.show_energy) energy_history_.clear();
  if (!batch_started_) update_recording();
}

}  // namespace wobble

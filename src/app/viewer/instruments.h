#ifndef WOBBLE_APP_VIEWER_INSTRUMENTS_H
#define WOBBLE_APP_VIEWER_INSTRUMENTS_H

#include <utility>
#include <vector>

#include "sim/instruments/convergence_trace.h"
#include "sim/instruments/frame_energy.h"

namespace wobble {

// The energy plot's samples, one a step, over the last seconds of simulated time.
struct EnergyHistory {
  std::vector<double> time, kinetic, spring, gravity, total;  // s, J
  void add(double time, const FrameEnergy& energy);
  void clear();
};

// The classroom instruments, a component of the viewer: the convergence of the last step and
// the energy over time. It owns what the plots show; the viewer hands it each finished batch's
// results (on the UI's side, between batches) and lets it draw once a frame. Which plots are
// open is the panel's setting, passed in.
class Instruments {
 public:
  // Whether a simulation must record its convergence: the plot is open, or a CSV asks
  // (set_convergence_required, which lasts through scene changes).
  bool wants_convergence(bool plot_open) const { return plot_open || convergence_required_; }
  void set_convergence_required(bool required) { convergence_required_ = required; }
  // Forget what was shown (a new scene, Reset).
  void clear();
  // A finished batch's results: its last step's trace (`trace_step` > 0 when it recorded one;
  // `trace` is taken) and the (time, energy) after each of its steps.
  void take(ConvergenceTrace& trace, long trace_step,
            const std::vector<std::pair<double, FrameEnergy>>& energy);
  // ImGui, between NewFrame and Render: the open plots, in a column at the window's right. A
  // plot the user closes clears its flag. Returns the column's left edge (ImGui's units), or
  // a negative number when no plot is open.
  float draw(bool& convergence_open, bool& energy_open, float ui_scale);

  const ConvergenceTrace& shown_trace() const { return shown_trace_; }
  const EnergyHistory& energy_history() const { return energy_history_; }

 private:
  bool convergence_required_ = false;
  ConvergenceTrace shown_trace_;  // what the convergence window shows
  long shown_trace_step_ = 0;
  EnergyHistory energy_history_;
};

}  // namespace wobble

#endif

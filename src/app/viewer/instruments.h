#ifndef WOBBLE_APP_VIEWER_INSTRUMENTS_H
#define WOBBLE_APP_VIEWER_INSTRUMENTS_H

#include <string>
#include <utility>
#include <vector>

#include "sim/instruments/convergence_trace.h"
#include "sim/instruments/frame_energy.h"
#include "ui/panel_sections.h"

namespace wobble {

// The energy plot's samples, one a step, over the last seconds of simulated time.
struct EnergyHistory {
  std::vector<double> time, kinetic, spring, gravity, total;  // s, J
  void add(double time, const FrameEnergy& energy);
  void clear();
};

// Which sides the plots show: the simulation alone, or with the view split both sides, each
// named by its solver's label ("local-global (Chebyshev)", "L-BFGS").
struct PlottedSides {
  bool split = false;
  std::string left_solver, right_solver;
};

// The classroom instruments, a component of the viewer: the convergence of the last step and
// the energy over time, of the simulation or, with the view split, of both sides. It owns which
// plots are open (the panel's "instruments" section, which it draws, and G) and what they show;
// the viewer hands it each finished batch's results (on the UI's side, between batches) and
// lets it draw once a frame.
class Instruments {
 public:
  // The panel's "instruments" section (panel_sections.h); returns whether its CSV button was
  // pressed.
  bool draw_panel_section() { return draw_instruments_section(open_); }
  // Open or close both plots (--plots).
  void open_both(bool open) { open_.show_convergence = open_.show_energy = open; }
  // G: both plots together, since a class wants the two side by side; open unless both are.
  void toggle_both() { open_both(!(open_.show_convergence && open_.show_energy)); }
  bool convergence_open() const { return open_.show_convergence; }
  bool energy_open() const { return open_.show_energy; }
  // Whether either plot is open: the plots' column stands at the window's right.
  bool column_open() const { return convergence_open() || energy_open(); }

  // Whether a simulation must record its convergence: the plot is open, or a CSV asks
  // (set_convergence_required, which lasts through scene changes).
  bool wants_convergence() const { return open_.show_convergence || convergence_required_; }
  void set_convergence_required(bool required) { convergence_required_ = required; }
  // Forget what was shown (a new scene, Reset).
  void clear();
  // A finished batch's results: its last step's trace (`trace_step` > 0 when it recorded one;
  // `trace` is taken) and the (time, energy) after each of its steps.
  void take(ConvergenceTrace& trace, long trace_step,
            const std::vector<std::pair<double, FrameEnergy>>& energy);
  // The same for the split view's right side, whose steps the batch also took.
  void take_right(ConvergenceTrace& trace, long trace_step,
                  const std::vector<std::pair<double, FrameEnergy>>& energy);
  // Which sides there are now; the right side's curves are forgotten when the view is not split.
  void set_sides(PlottedSides sides);
  // ImGui, between NewFrame and Render: the open plots, in a column at the window's right, clear
  // of the panel whose right edge is `panel_right` (0: hidden) where it can be. A plot the user
  // closes is closed. Returns the column's left edge (ImGui's units), or a negative number when
  // no plot is open.
  float draw(float ui_scale, float panel_right = 0.0f);

  // What the plots show as CSV text: the convergence plot's step (the simulation's, the left
  // side's) as --convergence-csv writes a step ("" when no step was traced yet), and the energy
  // plot's samples, time,kinetic,spring,gravity,total (s, J) a row.
  std::string convergence_csv() const;
  std::string energy_csv() const;
  const ConvergenceTrace& shown_trace() const { return left_.trace; }
  const EnergyHistory& energy_history() const { return left_.energy; }
  const ConvergenceTrace& shown_right_trace() const { return right_.trace; }
  const EnergyHistory& right_energy_history() const { return right_.energy; }

 private:
  // What the plots show of one side.
  struct Shown {
    ConvergenceTrace trace;  // its last step's
    long trace_step = 0;     // which step that was; 0: none yet
    EnergyHistory energy;
    void take(ConvergenceTrace& trace, long trace_step,
              const std::vector<std::pair<double, FrameEnergy>>& energy);
    void clear();
  };

  InstrumentSettings open_;  // which plots are open
  bool convergence_required_ = false;
  PlottedSides sides_;
  Shown left_, right_;  // the simulation's (the left side's), and the split view's right side's
};

}  // namespace wobble

#endif

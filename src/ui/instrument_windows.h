#ifndef WOBBLE_UI_INSTRUMENT_WINDOWS_H
#define WOBBLE_UI_INSTRUMENT_WINDOWS_H

#include <vector>

namespace wobble {

// How converged the last step looks (the app classifies it; see sim/instruments).
enum class ConvergenceLight { green, amber, red };

// The last step's iterations, as plain numbers: entry i after i iterations (0: the first
// iterate).
struct ConvergencePlotData {
  const std::vector<double>* energy = nullptr;         // J, the step's objective
  const std::vector<double>* gradient_norm = nullptr;  // N
  bool chebyshev = false;
  ConvergenceLight light = ConvergenceLight::green;
  double reduction = 0.0;  // last gradient norm over the first
  long step = 0;           // which step these are from
};

// The energy over the last seconds: one entry a step.
struct EnergyPlotData {
  const std::vector<double>* time = nullptr;  // s
  const std::vector<double>* kinetic = nullptr;
  const std::vector<double>* spring = nullptr;
  const std::vector<double>* gravity = nullptr;
  const std::vector<double>* total = nullptr;  // J
};

// The "Convergence" window: a green, amber or red light with a one-line hint, the gradient norm
// and the energy above the step's lowest, per iteration, on log axes. `open` is cleared by the
// window's close button.
void draw_convergence_window(const ConvergencePlotData& data, bool& open, float ui_scale);

// The "Energy" window: kinetic, spring, gravity and total energy over time.
void draw_energy_window(const EnergyPlotData& data, bool& open, float ui_scale);

// Width of the column the two windows open in at the right of the display (pixels): 380 at
// most, 45% of a small display. Other overlays keep out of it.
float instrument_column_width(float display_width, float ui_scale);
// Where that column begins (pixels from the display's left edge): its width and a margin from
// the right edge. The split view keeps left of it.
float instrument_column_left(float display_width, float ui_scale);

// The light's words, e.g. "converged", and the hint shown under it (empty when green).
const char* convergence_label(ConvergenceLight light);
const char* convergence_hint(ConvergenceLight light);

}  // namespace wobble

#endif

#ifndef WOBBLE_UI_INSTRUMENT_WINDOWS_H
#define WOBBLE_UI_INSTRUMENT_WINDOWS_H

#include <optional>
#include <string>
#include <vector>

namespace wobble {

// How converged the last step looks (the app classifies it; see sim/instruments).
enum class ConvergenceLight { green, amber, red };

// One side's last step, its iterations as plain numbers: entry i after i iterations (0: the
// first iterate).
struct ConvergenceCurve {
  const std::vector<double>* energy = nullptr;         // J, the step's objective
  const std::vector<double>* gradient_norm = nullptr;  // N
  std::string solver = "local-global";  // its label, e.g. "local-global (Chebyshev)", "L-BFGS"
  // How its iterations read in a sentence: "plain", "Chebyshev" or "L-BFGS".
  std::string method = "plain";
  ConvergenceLight light = ConvergenceLight::green;
  double reduction = 0.0;         // last gradient norm over the first
  long step = 0;                  // which step these are from
  bool chebyshev_applies = true;  // the hint may suggest Chebyshev (local-global, not on yet)
};

// What the convergence window shows: the simulation's last step, or with the view split both
// sides', left and right, as two curves on each plot.
struct ConvergencePlotData {
  ConvergenceCurve left;
  std::optional<ConvergenceCurve> right;  // the split view's right side
};

// The energy over the last seconds: one entry a step. With the view split, the two sides' total
// energies instead, each over its own steps' times.
struct EnergyPlotData {
  const std::vector<double>* time = nullptr;  // s
  const std::vector<double>* kinetic = nullptr;
  const std::vector<double>* spring = nullptr;
  const std::vector<double>* gravity = nullptr;
  const std::vector<double>* total = nullptr;  // J
  // The split view's right side: its times (s) and total energies (J), and each side's solver
  // label; null when the view is not split.
  const std::vector<double>* right_time = nullptr;
  const std::vector<double>* right_total = nullptr;
  std::string left_solver, right_solver;
};

// The "Convergence" window: a green, amber or red light (one a side) with a one-line hint, the
// gradient norm and the energy above the step's lowest, per iteration, on log axes, each curve
// named by its solver. `open` is cleared by the window's close button.
// `panel_right`: the panel's right edge (pixels; 0 when hidden), which the column keeps clear of.
void draw_convergence_window(const ConvergencePlotData& data, bool& open, float ui_scale,
                             float panel_right = 0.0f);

// The "Energy" window: kinetic, spring, gravity and total energy over time; with the view split,
// the two sides' total energies.
void draw_energy_window(const EnergyPlotData& data, bool& open, float ui_scale,
                        float panel_right = 0.0f);

// Width of the column the two windows open in at the right of the display (pixels): 380 times
// the UI scale at most, 45% of a small display, and narrower where the panel (its right edge at
// `panel_right`, 0 when hidden) would otherwise leave the shape less than
// column_free_share of the display between them (a projector's UI scale of 1.5 at 1280 wide),
// though not below min_column_width times the UI scale. Other overlays keep out of it.
constexpr float column_free_share = 0.3f;
constexpr float min_column_width = 200.0f;
float instrument_column_width(float display_width, float ui_scale, float panel_right = 0.0f);
// Where that column begins (pixels from the display's left edge): its width and a margin from
// the right edge. The split view keeps left of it.
float instrument_column_left(float display_width, float ui_scale, float panel_right = 0.0f);

// The light's words, e.g. "converged", and the hint shown under it (only when red); the hint
// suggests Chebyshev only where it would help (`chebyshev_applies`: local-global, not on yet).
const char* convergence_label(ConvergenceLight light);
// `value` as a legend writes it beside others read against `scale` (the largest of them): four
// significant digits of the scale and as many decimals for every value ("1.795", "0.016",
// "0.003" against 1.8), so that the legend keeps its width from frame to frame.
std::string legend_number(double value, double scale);
const char* convergence_hint(ConvergenceLight light, bool chebyshev_applies = true);

}  // namespace wobble

#endif

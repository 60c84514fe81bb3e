#ifndef WOBBLE_APP_OUTPUTS_INSTRUMENT_CSV_H
#define WOBBLE_APP_OUTPUTS_INSTRUMENT_CSV_H

#include <string>

#include "sim/instruments/convergence_trace.h"
#include "sim/simulation.h"

namespace wobble {

// --convergence-csv and --energy-csv: the classroom instruments as files, for graders and CI.
//
// convergence: frame,iteration,energy,gradient_norm,solver
//   one row per iterate of every step: iteration 0 is the step's first iterate, iteration i the
//   iterate after i iterations; energy is the step's objective in J (springs, inertia, −pᵀf_ext
//   and the pin term; see sim/instruments/step_objective.h), gradient_norm the norm of its
//   gradient in N, solver the registered name of the solver that took the step ("local-global",
//   "lbfgs"). The solver is the last column, so that readers of the first four by position or
//   by name read them as before.
// energy: frame,time,kinetic,spring,gravity,potential,total
//   one row per frame, frame 0 being the initial state; J (see sim/instruments/frame_energy.h).
//
// The rows are kept in memory and each file is written atomically at the end of the run (or
// when it stops early), so a reader never sees half a file.
// The convergence file's header and one step's rows (frame `step`), as --convergence-csv writes
// them: what the window's and the page's "CSV" button write of the step the plot shows.
extern const char* const convergence_csv_header;
void append_convergence_rows(std::string& out, long step, const ConvergenceTrace& trace);
// The shortest text that reads back as `value`, after a comma.
void append_csv_value(std::string& out, double value);

class InstrumentCsv {
 public:
  // Empty paths write nothing. Throws InputError naming the option when a path cannot be
  // written, or when `frames` steps of `iterations` would make more than max_rows rows.
  InstrumentCsv(std::string convergence_path, std::string energy_path, long frames, int iterations);

  // Whether the simulation must record its convergence (Simulation::set_convergence_recording).
  bool wants_convergence() const { return !convergence_path_.empty(); }
  // Takes the energy of frame 0, before the first step.
  void start(const Simulation& simulation);
  // After step `frame` (1, 2, …) was taken. Rows past max_rows (a window whose iteration slider
  // was raised past the count the estimate used) are left out.
  void record(long frame, const Simulation& simulation);
  // Writes the files asked for. Throws OutputError when one cannot be written.
  void write() const;

  // Rows one file may hold (about 100 MB of text).
  static constexpr long max_rows = 2'000'000;

 private:
  std::string convergence_path_, energy_path_;
  std::string convergence_, energy_;  // the CSV text so far
  long convergence_rows_ = 0, energy_rows_ = 0;
};

}  // namespace wobble

#endif

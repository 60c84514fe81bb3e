#ifndef WOBBLE_APP_VIEWER_RIGHT_SIDE_H
#define WOBBLE_APP_VIEWER_RIGHT_SIDE_H

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/cli/compare_settings.h"
#include "app/student/student_step.h"
#include "sim/instruments/convergence_trace.h"
#include "sim/instruments/frame_energy.h"
#include "sim/scene.h"
#include "sim/simulation.h"
#include "ui/panel_sections.h"

namespace wobble {

// What the right side's steps recorded for the plots since the viewer last took them.
struct RightSideSamples {
  ConvergenceTrace trace;  // its last step's, while its convergence is recorded
  long trace_step = 0;     // which of its steps that was; 0: none recorded
  std::vector<std::pair<double, FrameEnergy>> energy;  // (time, energy) after each of its steps
};

// The split view's right side, a component of the viewer: the same scene stepped with its own
// iterations, solver, Chebyshev, dt and k (--compare, the 2 key), or a student's
// fast_mass_springs_step_sparse in a process of its own (--student). It owns that simulation,
// how far it is behind the left side, why it stopped, and the student's step; everything else
// (pins and drags, gravity, damping, wind, friction, colliders) it copies from the left side,
// which the viewer hands it read-only, before each of its steps. It also owns the panel's
// "compare" section: the split view's checkbox and the compared side's settings, drawn on the
// UI's side and applied by the viewer between batches. Everything else is called on the
// simulation's side of the viewer only (between batches, or by the batch itself).
class RightSide {
 public:
  // Below this distance (m) a student's vertex counts as on Wobble's: rounding differences of
  // two correct implementations are far smaller, a wrong step far larger.
  static constexpr double distance_floor = 1e-6;

  // `student_server`: the step server built from a student's folder (student_server.h), or
  // empty for none.
  explicit RightSide(std::string student_server) : student_server_(std::move(student_server)) {}

  // The UI's side: the panel's "compare" section (panel_sections.h).
  void draw_panel_section() { draw_split_section(panel_, student()); }
  // Whether the section's checkbox asks for a split view (2 flips it).
  bool split_asked() const { return panel_.split; }
  void ask_split(bool split) { panel_.split = split; }

  // Whether wobble --student asked for a student's step on the right.
  bool wants_student() const { return !student_server_.empty(); }
  // The right side's simulation (a student's side is drawn from one that is never stepped),
  // or null when the view is not split.
  const Simulation* simulation() const { return simulation_.get(); }
  bool student() const { return student_ != nullptr; }
  // Why the right side stopped (a student's step that crashed or hung, a failed step), or empty.
  const std::string& warning() const { return warning_; }
  // With a student's step: its largest distance from the left side's positions after the last
  // step (m), and each vertex's colour by that distance (#V by 3 floats, RGB in [0, 1]).
  double student_distance() const { return student_distance_; }
  const std::vector<float>& student_colors() const { return student_colors_; }

  // Compare `settings` against `left`, from its current state; the section shows them.
  void start_compare(const Scene& scene, const Simulation& left, const CompareSettings& settings);
  // The student's step beside `left` (a server that does not start leaves its error as the
  // warning).
  void start_student(const Scene& scene, const Simulation& left);
  // No right side any more.
  void stop();
  // The compared side's settings.
  CompareSettings settings() const;
  // The section's settings applied to the compared side (the iterations clamped to what its
  // mesh allows, shown so).
  void apply();
  // `seconds` of simulated time after the left side stepped them: as many steps of the right
  // side's own dt (at most 16 a frame), or one of the student's.
  void advance(const Simulation& left, double seconds);
  // Back to the left side's state (Reset); a student's server that crashed is started afresh.
  void reset(const Scene& scene, const Simulation& left);
  // Record for the plots from the next step on, as the left side does while they are open: the
  // last step's convergence (the simulation records it only then) and the energy after each
  // step. Between batches.
  void record(bool convergence, bool energy);
  // What its steps recorded; the viewer takes them between batches and clears them.
  RightSideSamples& samples() { return samples_; }

 private:
  // Pins and their targets, colliders, gravity, damping, friction, wind and self-collision from
  // the left side.
  void sync(const Simulation& left);
  void advance_student(const Simulation& left);
  // After each of its good steps: what record() asked for.
  void take_samples();

  SplitSettings panel_;  // the "compare" section's, on the UI's side
  std::unique_ptr<Simulation> simulation_;
  double behind_ = 0.0;  // simulated time it is behind the left side (s)
  std::string warning_;
  std::string student_server_;
  std::unique_ptr<StudentStep> student_;
  double student_distance_ = 0.0;
  std::vector<float> student_colors_;
  bool record_convergence_ = false, record_energy_ = false;
  RightSideSamples samples_;
};

// The parameters under which Wobble's step is the seed's fast_mass_springs_step_sparse: 50 plain
// iterations from pᵗ, no damping, wind or colliders (the left side of wobble --student).
SimulationParams seed_method(SimulationParams params);

}  // namespace wobble

#endif

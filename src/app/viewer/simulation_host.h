#ifndef WOBBLE_APP_VIEWER_SIMULATION_HOST_H
#define WOBBLE_APP_VIEWER_SIMULATION_HOST_H

#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "app/interaction/drag_script.h"
#include "app/viewer/step_pacer.h"
#include "app/viewer/step_thread.h"
#include "sim/instruments/convergence_trace.h"
#include "sim/instruments/frame_energy.h"
#include "sim/simulation.h"

namespace wobble {

// What one batch of steps was asked for, and what it left for the UI.
struct Batch {
  int steps = 0;
  bool record_trace = false, record_energy = false;  // as the plots were open at its start
  int steps_taken = 0;
  std::vector<StepTiming> timings;  // of each good step
  ConvergenceTrace trace;           // the last step's, when recorded
  long trace_step = 0;
  std::vector<std::pair<double, FrameEnergy>> energy;  // (time, energy) after each step
  StepStatus status = StepStatus::ok;                  // the step that failed, if one did
  long failed_step = 0;
  bool scripted_drag = false;  // a scripted drag held a vertex at the failure
  double stiffness_ratio = 0.0;
};

// The simulation's side of the viewer, a component of it, as in MuJoCo's `simulate`: the
// simulation, its scripted drags and the batches of steps that advance it, on a thread of their
// own in the window (step_on_thread) or on the caller. While a batch runs the UI draws the state
// the last one left and keeps what the user does (change); the edits are handed over in order,
// at one point, once the batch finished and before the next one starts. Each step has its fixed
// dt, so N steps give the same positions on either thread.
//
// The simulation and the scripted drags are the batch's while one runs: the UI reads the
// simulation then only where the batch does not write (its colliders, its pins' count), and
// changes it through change().
class SimulationHost {
 public:
  Simulation& simulation() { return *simulation_; }
  const Simulation& simulation() const { return *simulation_; }
  // A new scene's simulation, between batches: the scripted drags are forgotten (their vertex
  // numbers belong to the first scene) and the real-time clock starts afresh.
  void replace(std::unique_ptr<Simulation> simulation);
  // Drags applied from the next step on (--drag), and Reset's starting them over.
  void set_drag_script(DragScript script) { drag_script_ = std::move(script); }
  void restart_drag_script() { drag_script_.restart(); }
  // After each good step, on the thread that took it: `after_step` (the viewer's split view),
  // then the observer (the window's CSV rows and OBJ sequences).
  void set_after_step(std::function<void(const Simulation&)> after_step) {
    after_step_ = std::move(after_step);
  }
  void set_step_observer(std::function<void(const Simulation&)> observer) {
    observer_ = std::move(observer);
  }

  // Do `what` now when no batch runs (returns true), else once the running batch finished,
  // after what was asked before it (returns false).
  bool change(std::function<void()> what);
  // The edits kept while a batch ran, in order, each on what the one before left.
  void hand_over_changes();
  bool changes_waiting() const { return !pending_.empty(); }

  // How many steps the next batch takes: one when one was asked for (`step_once`), none while
  // paused or at the step limit; headless (no `now`), with a step limit or without real time,
  // one; otherwise as many as keep up with the wall clock `now` (s) but fit in `frame_seconds`
  // (StepPacer), one step taking about `step_seconds`.
  int steps_to_start(bool step_once, bool paused, bool real_time, std::optional<double> now,
                     double frame_seconds, double step_seconds);
  // Start the real-time clock afresh (a new dt).
  void restart_clock() { pacer_.restart(); }
  // Stop after this many steps of each scene (the window's --frames, the page's frames=N): a
  // scene that replaces this one stops there again.
  void set_step_limit(long steps) {
    step_limit_ = steps;
    limit_passed_ = false;
  }
  // The steps taken reached the limit, and it was not passed.
  bool at_step_limit() const {
    return limit_applies() && simulation_ && simulation_->steps_taken() >= step_limit_;
  }
  // Go on past the limit (Play once the page paused there), until the next scene.
  void pass_step_limit() { limit_passed_ = true; }

  // Start a batch of `steps` steps, recording the last step's convergence trace and the energy
  // after each as asked; on the stepping thread once there is one, else finished on return.
  void start_batch(int steps, bool record_trace, bool record_energy);
  // A batch started whose results finish_batch has not taken.
  bool batch_started() const { return started_; }
  // A batch runs on the stepping thread now.
  bool stepping() const { return started_ && thread_ && thread_->running(); }
  // Wait for the started batch and take its results (an exception from the batch comes out
  // here), or null when none started. Valid until the next batch starts.
  Batch* finish_batch();
  // Wait for a started batch and drop its results and any error it met.
  void stop() noexcept;
  // Run batches on a thread of their own from now on; `wake` runs on it after each batch. Only
  // between batches.
  void step_on_thread(std::function<void()> wake);

 private:
  void run_batch();  // on the thread that takes the steps

  std::unique_ptr<Simulation> simulation_;
  DragScript drag_script_;
  std::function<void(const Simulation&)> after_step_, observer_;
  Batch batch_;
  bool started_ = false;
  std::unique_ptr<StepThread> thread_;          // null: batches run on the caller
  std::vector<std::function<void()>> pending_;  // the user's changes while a batch ran
  StepPacer pacer_;
  long step_limit_ = -1;       // < 0: none
  bool limit_passed_ = false;  // this scene went on past it
  bool limit_applies() const { return step_limit_ >= 0 && !limit_passed_; }
};

}  // namespace wobble

#endif

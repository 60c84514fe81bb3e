// The viewer's side of its steps: what it asks of the simulation host (simulation_host.h), and
// what a finished batch leaves for the UI (see the Viewer class comment).
#include <utility>

#include "app/viewer/step_advice.h"
#include "app/viewer/viewer.h"

namespace wobble {

void Viewer::change(std::function<void()> what) {
  // Made now: the next render reads the state afresh.
  if (host_.change(std::move(what))) arrays_stale_ = true;
}

void Viewer::hand_over_changes() {
  host_.hand_over_changes();
  apply_panel_settings();
  update_recording();
}

int Viewer::steps_to_start(std::optional<double> now, double frame_seconds) {
  const bool step_once = step_requested_;
  step_requested_ = false;
  return host_.steps_to_start(step_once, panel_.paused, panel_.real_time, now, frame_seconds,
                              1e-3 * step_ms_.median());
}

void Viewer::start_batch(int steps) {
  // The split view's right side steps in the same batch and records for the same plots.
  right_.record(instruments_.convergence_open(), instruments_.energy_open());
  host_.start_batch(steps, instruments_.convergence_open(), instruments_.energy_open());
}

void Viewer::finish_batch() {
  Batch* batch = host_.finish_batch();
  if (batch == nullptr) return;
  for (const StepTiming& timing : batch->timings) {
    step_ms_.add(static_cast<float>(timing.total_ms));
    local_ms_.add(static_cast<float>(timing.local_ms));
    global_ms_.add(static_cast<float>(timing.global_ms));
  }
  if (!batch->timings.empty()) last_timing_ = batch->timings.back();
  instruments_.take(batch->trace, batch->trace_step, batch->energy);
  RightSideSamples& right = right_.samples();
  instruments_.take_right(right.trace, right.trace_step, right.energy);
  right.trace_step = 0;
  right.energy.clear();
  if (batch->steps_taken > 0) step_warning_.clear();
  if (batch->status != StepStatus::ok) {
    panel_.paused = true;
    FailedStep failed;
    failed.status = batch->status;
    failed.step = batch->failed_step;
    failed.initial_velocity =
        scene_.initial_velocity.size() != 0 && !scene_.initial_velocity.isZero(0.0);
    failed.dragging = pick_and_drag_.held_vertex() >= 0 || batch->scripted_drag;
    failed.stiffness_ratio = batch->stiffness_ratio;
    failed.dt = host_.simulation().params().dt;
    step_warning_ = describe_failed_step(failed);
  }
}

void Viewer::advance() {
  finish_batch();
  hand_over_changes();
  if (steps_to_start(std::nullopt, 0.0) > 0) {
    start_batch(1);
    finish_batch();
  }
  refresh_shown_state();
}

bool Viewer::exchange(double now, double frame_seconds) {
  if (stepping()) return false;
  finish_batch();
  hand_over_changes();
  refresh_shown_state();
  // At the step limit (the page's frames=N) the simulation is paused, as the button then says;
  // Play goes on from there, and a scene opened next runs to the limit again. (The window's
  // --frames ends the run once step N is drawn.)
  if (!panel_.paused) paused_at_limit_ = false;
  if (host_.at_step_limit()) {
    panel_.paused = true;
    paused_at_limit_ = true;
    host_.pass_step_limit();
  }
  const int steps = steps_to_start(now, frame_seconds);
  if (steps > 0) start_batch(steps);
  return true;
}

void Viewer::step_on_thread(std::function<void()> wake) {
  finish_steps();
  host_.step_on_thread(std::move(wake));
}

void Viewer::finish_steps() {
  finish_batch();
  hand_over_changes();
  refresh_shown_state();
}

void Viewer::stop_stepping() noexcept {
  host_.stop();
}

void Viewer::refresh_shown_state() {
  update_vertex_arrays();
  update_quantity_colors();
  copy_shown_figures();
}

void Viewer::copy_shown_figures() {
  shown_stats_ = simulation_stats();
  shown_twin_warning_ = right_.warning();
  shown_student_distance_ = right_.student_distance();
  shown_student_colors_ = right_.student_colors();
  describe_sides();
}

}  // namespace wobble

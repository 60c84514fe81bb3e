// The viewer's steps: batches of steps, on the window's stepping thread or on the caller, and
// what passes between them and the UI (see the Viewer class comment).
#include <algorithm>
#include <utility>

#include "app/viewer/step_advice.h"
#include "app/viewer/viewer.h"
#include "sim/instruments/frame_energy.h"

namespace wobble {

void Viewer::change(std::function<void()> what) {
  if (batch_started_) {
    pending_.push_back(std::move(what));
  } else {
    what();
    arrays_stale_ = true;  // the next render reads the state afresh
  }
}

void Viewer::hand_over_changes() {
  // A change may load a scene and so forget the rest; each runs on what the one before left.
  std::vector<std::function<void()>> changes;
  changes.swap(pending_);
  for (const std::function<void()>& what : changes)
    what();
  apply_panel_settings();
  update_recording();
}

int Viewer::steps_to_start(std::optional<double> now, double frame_seconds) {
  const bool below_limit = step_limit_ < 0 || simulation_->steps_taken() < step_limit_;
  if (step_requested_) {
    step_requested_ = false;
    pacer_.restart();
    return below_limit ? 1 : 0;
  }
  if (panel_.paused || !below_limit) {
    pacer_.restart();  // playing again starts the real-time clock afresh
    return 0;
  }
  // Headless, and the window's --frames: every step drawn, as fast as the machine goes; without
  // real time, a step a frame.
  if (!now || !panel_.real_time || step_limit_ >= 0) return 1;
  const double step_seconds = 1e-3 * step_ms_.median();
  const int steps = pacer_.steps_due(*now, simulation_->params().dt, step_seconds, frame_seconds);
  if (step_limit_ < 0) return steps;
  return static_cast<int>(std::min<long>(steps, step_limit_ - simulation_->steps_taken()));
}

void Viewer::start_batch(int steps) {
  batch_ = Batch();
  batch_.steps = steps;
  batch_.record_trace = instruments_.convergence_open();
  batch_.record_energy = instruments_.energy_open();
  batch_.timings.reserve(steps);
  batch_started_ = true;
  if (step_thread_) {
    step_thread_->start([this] { run_batch(); });
  } else {
    run_batch();
  }
}

void Viewer::run_batch() {
  for (int i = 0; i < batch_.steps; ++i) {
    const long step = simulation_->steps_taken() + 1;
    drag_script_.before_step(*simulation_, step);
    const StepStatus status = simulation_->step();
    if (status != StepStatus::ok) {
      batch_.status = status;
      batch_.failed_step = step;
      batch_.scripted_drag = drag_script_.holds_vertex();
      batch_.stiffness_ratio = stiffness_ratio(*simulation_);
      return;
    }
    ++batch_.steps_taken;
    batch_.timings.push_back(simulation_->last_step_timing());
    if (batch_.record_trace) {
      const ConvergenceTrace& trace = simulation_->last_convergence();
      batch_.trace.energy.assign(trace.energy.begin(), trace.energy.end());
      batch_.trace.gradient_norm.assign(trace.gradient_norm.begin(), trace.gradient_norm.end());
      batch_.trace.chebyshev = trace.chebyshev;
      batch_.trace_step = step;
    }
    if (batch_.record_energy) {
      batch_.energy.emplace_back(simulation_->time(), frame_energy(*simulation_));
    }
    right_.advance(*simulation_, simulation_->params().dt);
    if (step_observer_) step_observer_(*simulation_);
  }
}

void Viewer::finish_batch() {
  if (!batch_started_) return;
  batch_started_ = false;
  if (step_thread_) step_thread_->wait();  // an exception from the batch comes out here
  for (const StepTiming& timing : batch_.timings) {
    step_ms_.add(static_cast<float>(timing.total_ms));
    local_ms_.add(static_cast<float>(timing.local_ms));
    global_ms_.add(static_cast<float>(timing.global_ms));
  }
  if (!batch_.timings.empty()) last_timing_ = batch_.timings.back();
  instruments_.take(batch_.trace, batch_.trace_step, batch_.energy);
  if (batch_.steps_taken > 0) step_warning_.clear();
  if (batch_.status != StepStatus::ok) {
    panel_.paused = true;
    FailedStep failed;
    failed.status = batch_.status;
    failed.step = batch_.failed_step;
    failed.initial_velocity =
        scene_.initial_velocity.size() != 0 && !scene_.initial_velocity.isZero(0.0);
    failed.dragging = pick_and_drag_.held_vertex() >= 0 || batch_.scripted_drag;
    failed.stiffness_ratio = batch_.stiffness_ratio;
    failed.dt = simulation_->params().dt;
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
  const int steps = steps_to_start(now, frame_seconds);
  if (steps > 0) start_batch(steps);
  return true;
}

void Viewer::step_on_thread(std::function<void()> wake) {
  finish_steps();
  step_thread_ = std::make_unique<StepThread>(std::move(wake));
}

void Viewer::finish_steps() {
  finish_batch();
  hand_over_changes();
  refresh_shown_state();
}

void Viewer::stop_stepping() noexcept {
  if (!batch_started_) return;
  batch_started_ = false;
  try {
    if (step_thread_) step_thread_->wait();
  } catch (...) {  // the run already fails for another reason
  }
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

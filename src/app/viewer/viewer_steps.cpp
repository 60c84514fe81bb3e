// The viewer's side of its steps: what it asks of the session's simulation host
// (simulation_host.h), and what a finished batch leaves for the UI (see the Viewer class
// comment).
#include <utility>

#include "app/viewer/viewer.h"

namespace wobble {

void Viewer::change(std::function<void()> what) {
  // Made now: the next render reads the state afresh.
  if (host_.change(std::move(what))) drawing_.mark_stale();
}

void Viewer::hand_over_changes() {
  host_.hand_over_changes();
  apply_panel_settings();
  session_.update_recording();
}

void Viewer::start_batch(int steps) {
  session_.start_batch(steps);
}

void Viewer::finish_batch() {
  if (session_.finish_batch(pick_and_drag_.held_vertex() >= 0)) panel_.paused = true;
}

void Viewer::advance() {
  finish_batch();
  hand_over_changes();
  if (session_.steps_to_start(panel_.paused, panel_.real_time, std::nullopt, 0.0) > 0) {
    start_batch(1);
    finish_batch();
  }
  refresh_shown_state();
}

bool Viewer::exchange(double now, double frame_seconds) {
  if (session_.stepping()) return false;
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
  const int steps = session_.steps_to_start(panel_.paused, panel_.real_time, now, frame_seconds);
  if (steps > 0) start_batch(steps);
  return true;
}

void Viewer::finish_steps() {
  finish_batch();
  hand_over_changes();
  refresh_shown_state();
}

bool Viewer::animating() const {
  return !panel_.paused || session_.one_step_asked() || pick_and_drag_.busy() ||
         host_.batch_started() || host_.changes_waiting();
}

void Viewer::refresh_shown_state() {
  update_vertex_arrays();
  update_quantity_colors();
  session_.copy_shown_figures();
}

}  // namespace wobble

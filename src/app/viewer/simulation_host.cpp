// The simulation's side of the viewer: batches of steps, on the window's stepping thread or on
// the caller, and the user's edits handed over between them.
#include "app/viewer/simulation_host.h"

#include <algorithm>

#include "app/viewer/step_advice.h"

namespace wobble {

void SimulationHost::replace(std::unique_ptr<Simulation> simulation) {
  pacer_.restart();
  drag_script_ = DragScript();
  limit_passed_ = false;  // the new scene stops at the limit again
  simulation_ = std::move(simulation);
}

bool SimulationHost::change(std::function<void()> what) {
  if (started_) {
    pending_.push_back(std::move(what));
    return false;
  }
  what();
  return true;
}

void SimulationHost::hand_over_changes() {
  // A change may load a scene and so forget the rest; each runs on what the one before left.
  std::vector<std::function<void()>> changes;
  changes.swap(pending_);
  for (const std::function<void()>& what : changes)
    what();
}

int SimulationHost::steps_to_start(bool step_once, bool paused, bool real_time,
                                   std::optional<double> now, double frame_seconds,
                                   double step_seconds) {
  const bool below_limit = !limit_applies() || simulation_->steps_taken() < step_limit_;
  if (step_once) {
    pacer_.restart();
    return below_limit ? 1 : 0;
  }
  if (paused || !below_limit) {
    pacer_.restart();  // playing again starts the real-time clock afresh
    return 0;
  }
  // Headless, and the window's --frames: every step drawn, as fast as the machine goes; without
  // real time, a step a frame.
  if (!now || !real_time || limit_applies()) return 1;
  const int steps = pacer_.steps_due(*now, simulation_->params().dt, step_seconds, frame_seconds);
  if (!limit_applies()) return steps;
  return static_cast<int>(std::min<long>(steps, step_limit_ - simulation_->steps_taken()));
}

void SimulationHost::start_batch(int steps, bool record_trace, bool record_energy) {
  batch_ = Batch();
  batch_.steps = steps;
  batch_.record_trace = record_trace;
  batch_.record_energy = record_energy;
  batch_.timings.reserve(steps);
  started_ = true;
  if (thread_) {
    thread_->start([this] { run_batch(); });
  } else {
    run_batch();
  }
}

void SimulationHost::run_batch() {
  Simulation& simulation = *simulation_;
  for (int i = 0; i < batch_.steps; ++i) {
    const long step = simulation.steps_taken() + 1;
    drag_script_.before_step(simulation, step);
    const StepStatus status = simulation.step();
    if (status != StepStatus::ok) {
      batch_.status = status;
      batch_.failed_step = step;
      batch_.scripted_drag = drag_script_.holds_vertex();
      batch_.stiffness_ratio = stiffness_ratio(simulation);
      return;
    }
    ++batch_.steps_taken;
    batch_.timings.push_back(simulation.last_step_timing());
    if (batch_.record_trace) {
      const ConvergenceTrace& trace = simulation.last_convergence();
      // The whole record, its force scale included (what the light measures a step at rest
      // by); the vectors keep their buffers.
      batch_.trace = trace;
      batch_.trace_step = step;
    }
    if (batch_.record_energy) {
      batch_.energy.emplace_back(simulation.time(), frame_energy(simulation));
    }
    if (after_step_) after_step_(simulation);
    if (observer_) observer_(simulation);
  }
}

Batch* SimulationHost::finish_batch() {
  if (!started_) return nullptr;
  started_ = false;
  if (thread_) thread_->wait();  // an exception from the batch comes out here
  return &batch_;
}

void SimulationHost::stop() noexcept {
  if (!started_) return;
  started_ = false;
  try {
    if (thread_) thread_->wait();
  } catch (...) {  // the run already fails for another reason
  }
}

void SimulationHost::step_on_thread(std::function<void()> wake) {
  thread_ = std::make_unique<StepThread>(std::move(wake));
}

}  // namespace wobble

// The split view's right side: the same scene twice, left and right, each with its own
// iterations, solver, Chebyshev, dt and k, stepping together from the same state under the same
// camera; or, with wobble --student, a student's fast_mass_springs_step_sparse on the right, each
// vertex coloured by how far it is from Wobble's. The student's step runs in its own process
// (student_step.h): a crash or an endless loop stops the right side with the reason written in
// its corner, and the viewer goes on.
#include "app/viewer/right_side.h"

#include <algorithm>

#include "app/cli/solver_choice.h"
#include "app/viewer/quantity_colors.h"
#include "app/viewer/side_settings.h"
#include "sim/contact/collider_contact_term.h"

namespace wobble {

namespace {

// A right side with a much smaller dt takes several steps a frame; beyond this many it falls
// behind instead of stalling the window.
constexpr int max_steps_per_frame = 16;

}  // namespace

SimulationParams seed_method(SimulationParams params) {
  // What fast_mass_springs_step_sparse does: 50 plain iterations from pᵗ, gravity and the pins,
  // nothing else.
  params.iterations = 50;
  params.chebyshev = false;
  params.first_iterate = FirstIterate::current_positions;
  params.damping = 0.0;
  params.wind.on = false;
  params.contact.colliders.clear();
  return params;
}

void RightSide::start_compare(const Scene& scene, const Simulation& left,
                              const CompareSettings& settings) {
  auto simulation = std::make_unique<Simulation>(
      scene.network, scene.pins, settings.applied_to(left.params()), scene.initial_velocity);
  simulation->set_state(left.positions(), left.previous_positions());
  simulation->set_convergence_recording(record_convergence_);
  simulation_ = std::move(simulation);
  behind_ = 0.0;
  warning_.clear();
  samples_ = RightSideSamples();
  sync(left);
  panel_.split = true;
  show_settings(simulation_->params(), panel_.right, scene.network.T.rows() > 0);
}

void RightSide::start_student(const Scene& scene, const Simulation& left) {
  const SpringNetwork& network = scene.network;
  const std::vector<int> pins = left.pinned_vertices();
  Eigen::VectorXi b(static_cast<Eigen::Index>(pins.size()));
  for (std::size_t i = 0; i < pins.size(); ++i)
    b(static_cast<Eigen::Index>(i)) = pins[i];
  student_ = std::make_unique<StudentStep>(student_server_, network.V, network.E, left.params().k,
                                           network.m, b, left.params().dt);
  // The right side's shape lives in a simulation that is never stepped, only given the
  // student's positions: it draws, colours and frames like any other side.
  simulation_ =
      std::make_unique<Simulation>(network, scene.pins, left.params(), scene.initial_velocity);
  simulation_->set_state(left.positions(), left.previous_positions());
  warning_ = student_->running() ? "" : student_->error();
  panel_.split = true;
  student_distance_ = 0.0;
  student_colors_.assign(3 * static_cast<std::size_t>(network.V.rows()), 0.0f);
}

void RightSide::stop() {
  simulation_.reset();
  student_.reset();
  warning_.clear();
}

CompareSettings RightSide::settings() const {
  // Every setting the right side has its own of, as --compare would give it.
  CompareSettings settings;
  for (const std::string& name : overridable_setting_names())
    settings.values[name] = find_setting(name)->get(simulation_->params());
  return settings;
}

void RightSide::apply() {
  Simulation& right = *simulation_;
  right.apply(settings_from_sliders(right.params(), panel_.right, right.max_iterations_for_mesh()));
}

void RightSide::record(bool convergence, bool energy) {
  record_convergence_ = convergence;
  record_energy_ = energy;
  // A student's side is never stepped here: nothing to record.
  if (simulation_ && !student_ && simulation_->records_convergence() != convergence) {
    simulation_->set_convergence_recording(convergence);
  }
}

void RightSide::take_samples() {
  const Simulation& right = *simulation_;
  if (record_convergence_ && right.records_convergence()) {
    // Into the buffers the last batch's trace left, as the left side's batch does.
    const ConvergenceTrace& trace = right.last_convergence();
    // The whole record, its force scale included (what the light measures a step at rest by).
    samples_.trace = trace;
    samples_.trace_step = right.steps_taken();
  }
  if (record_energy_) samples_.energy.emplace_back(right.time(), frame_energy(right));
}

void RightSide::sync(const Simulation& left) {
  Simulation& right = *simulation_;
  // Pins: the same vertices, at the same targets.
  const std::vector<int> pins = left.pinned_vertices();
  if (pins != right.pinned_vertices()) {
    for (const int i : right.pinned_vertices()) {
      if (!left.is_pinned(i)) right.unpin(i);
    }
    for (const int i : pins) {
      if (!right.is_pinned(i)) right.pin(i);
    }
  }
  for (const int i : pins)
    right.set_pin_target(i, left.pin_target(i));
  // Colliders where the left side's are (an Alt+drag moves both).
  const std::vector<Collider>& lefts = colliders_in(left.terms());
  for (std::size_t c = 0; c < lefts.size(); ++c) {
    const Eigen::Vector3d offset =
        collider_anchor(lefts[c]) - collider_anchor(colliders_in(right.terms())[c]);
    if (!offset.isZero(0.0))
      right.term<ColliderContactTerm>()->translate(static_cast<int>(c), offset);
  }
  // The environment is the left side's; what each side steps with (k, dt, iterations, the
  // solver, Chebyshev, the added settings: those declared per_side) stays the right side's own.
  SimulationParams wanted = right.params();
  for (const SettingSpec& spec : all_settings()) {
    if (!spec.per_side) spec.set(wanted, spec.get(left.params()));
  }
  right.apply(wanted);
}

void RightSide::advance(const Simulation& left, double seconds) {
  if (student_) {
    advance_student(left);
    return;
  }
  if (!simulation_ || !warning_.empty()) return;
  sync(left);
  // Both sides cover the same simulated time: a right side with half the dt steps twice a frame.
  behind_ += seconds;
  const double dt = simulation_->params().dt;
  for (int step = 0; step < max_steps_per_frame && behind_ >= 0.5 * dt; ++step) {
    const StepStatus status = simulation_->step();
    if (status != StepStatus::ok) {
      warning_ = "right side stopped: " + Simulation::describe(status);
      return;
    }
    behind_ -= dt;
    take_samples();
  }
  // What a capped frame could not catch up is dropped, not carried into a burst later.
  behind_ = std::min(behind_, dt);
}

void RightSide::advance_student(const Simulation& left) {
  if (!warning_.empty()) return;
  Eigen::MatrixXd next;
  std::string error;
  if (!student_->step(left.external_forces(), simulation_->previous_positions(),
                      simulation_->positions(), next, error)) {
    warning_ = error;
    return;
  }
  const Eigen::MatrixXd now = simulation_->positions();
  try {
    simulation_->set_state(next, now);
  } catch (const std::exception& refused) {  // a NaN from the student's step
    warning_ = std::string("the student's step returned ") + refused.what();
    return;
  }
  const Eigen::VectorXd distance = (simulation_->positions() - left.positions()).rowwise().norm();
  student_distance_ = distance.maxCoeff();
  const double range = std::max(student_distance_, distance_floor);
  for (Eigen::Index i = 0; i < distance.size(); ++i) {
    const Eigen::Vector3f color = sequential_color(static_cast<float>(distance(i) / range));
    for (int c = 0; c < 3; ++c)
      student_colors_[3 * i + c] = color(c);
  }
}

void RightSide::reset(const Scene& scene, const Simulation& left) {
  if (!simulation_) return;
  simulation_->reset();
  simulation_->set_state(left.positions(), left.previous_positions());
  behind_ = 0.0;
  if (student_) {
    student_distance_ = 0.0;
    std::fill(student_colors_.begin(), student_colors_.end(), 0.0f);
    // A server that crashed or hung is started afresh; one that runs keeps its precomputation.
    if (!student_->running()) start_student(scene, left);
    warning_ = student_->running() ? "" : student_->error();
    return;
  }
  warning_.clear();
  samples_ = RightSideSamples();
  sync(left);
}

}  // namespace wobble

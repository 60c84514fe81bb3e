#include "app/viewer/viewer_session.h"

#include <algorithm>
#include <cstdio>
#include <utility>

#include "app/cli/scene_catalog.h"
#include "app/cli/solver_choice.h"
#include "app/viewer/step_advice.h"
#include "sim/contact/collider_contact_term.h"
#include "sim/parallel/worker_pool.h"
#include "ui/side_labels.h"

namespace wobble {

ViewerSession::ViewerSession(std::vector<std::string> sources, std::string source,
                             std::string student_server)
    : sources_(std::move(sources)), source_(std::move(source)), right_(std::move(student_server)) {
  for (const std::string& each : sources_) {
    labels_.push_back(scene_label(each));
    choices_.push_back(
        SceneChoice{labels_.back(), scene_description(each), is_course_scene_source(each)});
  }
  // After each step, on the thread that took it, the split view's right side catches up.
  host_.set_after_step([this](const Simulation& left) { right_.advance(left, left.params().dt); });
}

int ViewerSession::scene_index() const {
  return static_cast<int>(std::find(labels_.begin(), labels_.end(), scene_.name) - labels_.begin());
}

void ViewerSession::open(Scene scene, std::unique_ptr<Simulation> simulation) {
  step_warning_.clear();
  scene_ = std::move(scene);
  host_.replace(std::move(simulation));  // its scripted drags forgotten, its clock afresh
  instruments_.clear();
  update_recording();
  // The picker shows the scene as current; a scene from elsewhere joins the list.
  if (std::find(labels_.begin(), labels_.end(), scene_.name) == labels_.end()) {
    labels_.push_back(scene_.name);
    sources_.push_back(scene_.name);
  }
}

void ViewerSession::offer(const std::string& path) {
  if (!path.empty() && std::find(sources_.begin(), sources_.end(), path) == sources_.end()) {
    sources_.push_back(path);
    labels_.push_back(scene_label(path));
  }
}

PanelStats ViewerSession::stats() const {
  if (host_.batch_started()) return shown_stats_;
  return simulation_stats();
}

PanelStats ViewerSession::simulation_stats() const {
  const Simulation& simulation = host_.simulation();
  PanelStats stats;
  stats.vertices = static_cast<int>(scene_.network.V.rows());
  stats.springs = static_cast<int>(scene_.network.E.rows());
  stats.pins = simulation.pin_count() - (free_vertex_held_ && free_vertex_held_() ? 1 : 0);
  stats.threads = shared_thread_setting().threads;
  stats.steps = simulation.steps_taken();
  // The accepted steps' dt summed: a new dt changes the rate from now on, not the past.
  stats.simulated_seconds = simulation.time();
  stats.notes = scene_.notes;
  stats.has_colliders = !colliders_in(simulation.terms()).empty();
  stats.contacts =
      static_cast<int>(simulation.last_step_timing().figure("collider contact", "contacts"));
  stats.self_collision = simulation.params().self_collision.on;
  stats.self_contacts =
      static_cast<int>(simulation.last_step_timing().figure("self-contact", "contacts"));
  stats.student_side = right_.student();
  stats.course_scene = scene_.params.gravity_model == GravityModel::force_per_vertex;
  stats.solver = solver_label(simulation.params().solver);
  stats.warning = step_warning_;
  return stats;
}

PanelStats ViewerSession::step_times() const {
  PanelStats stats;
  stats.step_ms = step_ms_.median();
  stats.local_ms = local_ms_.median();
  stats.global_ms = global_ms_.median();
  stats.forces_ms = static_cast<float>(last_timing_.forces_ms);
  stats.instruments_ms = static_cast<float>(last_timing_.instruments_ms);
  for (const TermFigure& figure : last_timing_.figures) {
    stats.term_figures.push_back(PanelStats::TermFigure{figure.term, figure.name, figure.unit,
                                                        static_cast<float>(figure.value)});
  }
  return stats;
}

FrameTime ViewerSession::shown_time() const {
  // While a batch runs, the simulation is the stepping thread's: the copy taken before it.
  if (host_.batch_started()) return FrameTime{shown_stats_.simulated_seconds, shown_dt_};
  return FrameTime{host_.simulation().time(), host_.simulation().params().dt};
}

void ViewerSession::set_convergence_required(bool required) {
  instruments_.set_convergence_required(required);
  update_recording();
}

void ViewerSession::update_recording() {
  const bool on = instruments_.wants_convergence();
  if (host_.simulation().records_convergence() != on)
    host_.simulation().set_convergence_recording(on);
}

void ViewerSession::after_reset() {
  instruments_.clear();
  host_.restart_drag_script();
  step_warning_.clear();
}

int ViewerSession::steps_to_start(bool paused, bool real_time, std::optional<double> now,
                                  double frame_seconds) {
  const bool step_once = step_requested_;
  step_requested_ = false;
  return host_.steps_to_start(step_once, paused, real_time, now, frame_seconds,
                              1e-3 * step_ms_.median());
}

void ViewerSession::start_batch(int steps) {
  // The split view's right side steps in the same batch and records for the same plots.
  right_.record(instruments_.convergence_open(), instruments_.energy_open());
  host_.start_batch(steps, instruments_.convergence_open(), instruments_.energy_open());
}

bool ViewerSession::finish_batch(bool dragging) {
  Batch* batch = host_.finish_batch();
  if (batch == nullptr) return false;
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
  if (batch->status == StepStatus::ok) return false;
  FailedStep failed;
  failed.status = batch->status;
  failed.step = batch->failed_step;
  failed.initial_velocity =
      scene_.initial_velocity.size() != 0 && !scene_.initial_velocity.isZero(0.0);
  failed.dragging = dragging || batch->scripted_drag;
  failed.stiffness_ratio = batch->stiffness_ratio;
  failed.dt = host_.simulation().params().dt;
  step_warning_ = describe_failed_step(failed);
  return true;
}

void ViewerSession::copy_shown_figures() {
  shown_stats_ = simulation_stats();
  shown_dt_ = host_.simulation().params().dt;
  shown_twin_warning_ = right_.warning();
  shown_student_distance_ = right_.student_distance();
  shown_student_colors_ = right_.student_colors();
  describe_sides();
}

void ViewerSession::describe_sides() {
  shown_left_label_.clear();
  shown_right_label_.clear();
  const Simulation* right_side = right_.simulation();
  const SimulationParams& left = host_.simulation().params();
  PlottedSides sides;
  sides.split = right_side && !right_.student();
  sides.left_solver = solver_label(left.solver, left.chebyshev);
  if (sides.split) {
    sides.right_solver = solver_label(right_side->params().solver, right_side->params().chebyshev);
  }
  instruments_.set_sides(sides);
  if (!right_side) return;
  // The corners name the solvers once they differ or are not the default; two local-global
  // sides read as before, plain or Chebyshev.
  const std::string& right_solver = right_side->params().solver;
  const bool name_solver = left.solver != right_solver || left.solver != solver_names().front();
  shown_left_label_ = describe_side(left, name_solver);
  shown_right_label_ = describe_side(right_side->params(), name_solver);
  if (!right_.student()) return;
  const SimulationParams& params = right_side->params();
  char right[200];
  std::snprintf(right, sizeof(right),
                "the student's fast_mass_springs_step_sparse\ndt %.3g ms, k %g N/m\n"
                "largest distance from Wobble's: %.2g m",
                1000.0 * params.dt, params.k, right_.student_distance());
  shown_left_label_ = "Wobble's step (reference)\n" + shown_left_label_;
  shown_right_label_ = right;
}

}  // namespace wobble

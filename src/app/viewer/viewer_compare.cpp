// The split view: the same scene twice, left and right, each with its own iterations, Chebyshev,
// dt and k, stepping together from the same state under the same camera. Everything else (pins
// and their drags, gravity, damping, wind, friction, colliders) is the left side's, copied to
// the right before each of its steps, so a drag acts on both.
#include <algorithm>
#include <cstdio>

#include "app/viewer/viewer.h"
#include "ui/side_labels.h"

#include <imgui.h>

#include <algorithm>

namespace wobble {

namespace {

// A right side with a much smaller dt takes several steps a frame; beyond this many it falls
// behind instead of stalling the window.
constexpr int max_twin_steps_per_frame = 16;

}  // namespace

void Viewer::start_split(const CompareSettings& settings) {
  auto twin = std::make_unique<Simulation>(scene_.network, scene_.pins,
                                           settings.applied_to(simulation_->params()),
                                           scene_.initial_velocity);
  twin->set_state(simulation_->positions(), simulation_->previous_positions());
  twin_ = std::move(twin);
  twin_behind_ = 0.0;
  twin_warning_.clear();
  sync_twin();
  show_twin_in_panel();
  panel_.split = true;
  // A shape framed beside the panel (or by the scene's own camera, made for the whole window)
  // would sit off centre in both halves: each half frames it in its middle, from the same
  // direction.
  view_camera_.centre();
  view_camera_.frame_next();
  twin_positions_.resize(positions_.size());
  twin_normals_.resize(normals_.size());
  arrays_stale_ = true;  // the right side's arrays fill at the next refresh or render
}

void Viewer::stop_split() {
  twin_.reset();
  view_camera_.frame_next();  // the whole window again, beside the panel
  twin_warning_.clear();
  panel_.split = false;
}

void Viewer::show_twin_in_panel() {
  const SimulationParams& params = twin_->params();
  panel_.right_k = static_cast<float>(params.k);
  panel_.right_dt = static_cast<float>(params.dt);
  panel_.right_iterations = params.iterations;
  panel_.right_chebyshev = params.chebyshev;
}

CompareSettings Viewer::twin_settings() const {
  CompareSettings settings;
  const SimulationParams& params = twin_->params();
  settings.iterations = params.iterations;
  settings.chebyshev = params.chebyshev;
  settings.dt = params.dt;
  settings.k = params.k;
  return settings;
}

void Viewer::apply_split_settings() {
  if (student_) {  // the student's side stays, with the seed's settings
    panel_.split = true;
    return;
  }
  if (panel_.split && !twin_) start_split(default_compare_settings(simulation_->params()));
  if (!panel_.split && twin_) stop_split();
  if (!twin_) return;
  const SimulationParams& params = twin_->params();
  if (static_cast<float>(params.k) != panel_.right_k) twin_->set_k(panel_.right_k);
  if (static_cast<float>(params.dt) != panel_.right_dt) twin_->set_dt(panel_.right_dt);
  panel_.right_iterations = std::min(panel_.right_iterations, twin_->max_iterations_for_mesh());
  if (params.iterations != panel_.right_iterations) twin_->set_iterations(panel_.right_iterations);
  if (params.chebyshev != panel_.right_chebyshev) twin_->set_chebyshev(panel_.right_chebyshev);
}

void Viewer::sync_twin() {
  Simulation& twin = *twin_;
  const Simulation& main = *simulation_;
  // Pins: the same vertices, at the same targets.
  const std::vector<int> pins = main.pinned_vertices();
  if (pins != twin.pinned_vertices()) {
    for (const int i : twin.pinned_vertices()) {
      if (!main.is_pinned(i)) twin.unpin(i);
    }
    for (const int i : pins) {
      if (!twin.is_pinned(i)) twin.pin(i);
    }
  }
  for (const int i : pins)
    twin.set_pin_target(i, main.pin_target(i));
  // Colliders where the left side's are (an Alt+drag moves both).
  for (std::size_t c = 0; c < main.colliders().size(); ++c) {
    const Eigen::Vector3d offset =
        collider_anchor(main.colliders()[c]) - collider_anchor(twin.colliders()[c]);
    if (!offset.isZero(0.0)) twin.translate_collider(static_cast<int>(c), offset);
  }
  const SimulationParams& from = main.params();
  const SimulationParams& to = twin.params();
  if (from.gravity != to.gravity || from.gravity_model != to.gravity_model) {
    twin.set_gravity(from.gravity, from.gravity_model);
  }
  if (from.damping != to.damping) twin.set_damping(from.damping);
  if (from.contact.friction != to.contact.friction) twin.set_friction(from.contact.friction);
  const WindParams& wind = from.wind;
  const WindParams& twin_wind = to.wind;
  if (wind.on != twin_wind.on || wind.model != twin_wind.model ||
      wind.velocity != twin_wind.velocity || wind.gusts != twin_wind.gusts ||
      wind.drag != twin_wind.drag || wind.lift != twin_wind.lift ||
      wind.air_density != twin_wind.air_density) {
    twin.set_wind(wind);
  }
  const SelfCollisionParams& self = from.self_collision;
  if (self.on != to.self_collision.on || self.thickness != to.self_collision.thickness) {
    twin.set_self_collision(self);
  }
}

void Viewer::advance_twin(double seconds) {
  if (student_) {
    advance_student();
    return;
  }
  if (!twin_ || !twin_warning_.empty()) return;
  sync_twin();
  // Both sides cover the same simulated time: a right side with half the dt steps twice a frame.
  twin_behind_ += seconds;
  const double dt = twin_->params().dt;
  for (int step = 0; step < max_twin_steps_per_frame && twin_behind_ >= 0.5 * dt; ++step) {
    const StepStatus status = twin_->step();
    if (status != StepStatus::ok) {
      twin_warning_ = "right side stopped: " + Simulation::describe(status);
      return;
    }
    twin_behind_ -= dt;
  }
  // What a capped frame could not catch up is dropped, not carried into a burst later.
  twin_behind_ = std::min(twin_behind_, dt);
}

void Viewer::reset_twin() {
  if (student_) {
    restart_student();
    return;
  }
  if (!twin_) return;
  twin_->reset();
  twin_->set_state(simulation_->positions(), simulation_->previous_positions());
  twin_behind_ = 0.0;
  twin_warning_.clear();
  sync_twin();
}

void Viewer::draw_overlays(float ui_scale) {
  show_instruments(ui_scale);
  if (!twin_) return;
  SideLabels labels;
  labels.left = shown_left_label_;
  labels.right = shown_right_label_;
  labels.right_warning = shown_twin_warning_;
  const SplitArea area = split_area(ImGui::GetIO().DisplaySize.x);
  labels.area_left = area.left;
  labels.half = area.half;
  draw_side_labels(labels, ui_scale);
}

Viewer::SplitArea Viewer::split_area(float window) const {
  float left = panel_place_.shown ? panel_place_.x + panel_place_.width : 0.0f;
  float right = instruments_left_ >= 0.0f ? std::min(window, instruments_left_) : window;
  // Two halves narrower than a sixth of the window each show too little: then the whole
  // window, the panel and plots over it as before.
  if (right - left < window / 3.0f) {
    left = 0.0f;
    right = window;
  }
  return SplitArea{left, 0.5f * (right - left)};
}

void Viewer::describe_sides() {
  shown_left_label_.clear();
  shown_right_label_.clear();
  if (!twin_) return;
  shown_left_label_ = describe_side(simulation_->params());
  shown_right_label_ = describe_side(twin_->params());
  if (!student_) return;
  const SimulationParams& params = twin_->params();
  char right[200];
  std::snprintf(right, sizeof(right),
                "the student's fast_mass_springs_step_sparse\ndt %.3g ms, k %g N/m\n"
                "largest distance from Wobble's: %.2g m",
                1000.0 * params.dt, params.k, student_distance_);
  shown_left_label_ = "Wobble's step (reference)\n" + shown_left_label_;
  shown_right_label_ = right;
}

}  // namespace wobble

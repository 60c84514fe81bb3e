// The viewer's side of the split view: starting and stopping it from the panel and the keys,
// the area the two sides share, and their corner labels. The right side itself is a component
// (right_side.h).
#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "app/cli/solver_choice.h"
#include "app/viewer/quantity_colors.h"
#include "app/viewer/viewer.h"
#include "ui/color_legend.h"
#include "ui/side_labels.h"

namespace wobble {

void Viewer::start_split(const CompareSettings& settings) {
  right_.start_compare(scene_, host_.simulation(), settings);
  // A shape framed beside the panel (or by the scene's own camera, made for the whole window)
  // would sit off centre in both halves: each half frames it in its middle, from the same
  // direction.
  view_camera_.centre();
  view_camera_.frame_next();
  twin_positions_.resize(positions_.size());
  twin_normals_.resize(normals_.size());
  arrays_stale_ = true;  // the right side's arrays fill at the next refresh or render
}

void Viewer::start_student() {
  right_.start_student(scene_, host_.simulation());
  twin_positions_.resize(positions_.size());
  twin_normals_.resize(normals_.size());
}

void Viewer::stop_split() {
  right_.stop();
  view_camera_.frame_next();  // the whole window again, beside the panel
  right_.ask_split(false);
}

void Viewer::apply_split_settings() {
  if (right_.student()) {  // the student's side stays, with the seed's settings
    right_.ask_split(true);
    return;
  }
  if (right_.split_asked() && !right_.simulation()) {
    start_split(default_compare_settings(host_.simulation().params()));
  }
  if (!right_.split_asked() && right_.simulation()) stop_split();
  if (right_.simulation()) right_.apply();
}

void Viewer::draw_overlays(float ui_scale) {
  show_instruments(ui_scale);
  if (!right_.simulation()) return;
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

void Viewer::draw_student_legend(float ui_scale) {
  constexpr double distance_floor = RightSide::distance_floor;
  ColorLegend legend;
  constexpr int samples = 17;
  for (int i = 0; i < samples; ++i) {
    const Eigen::Vector3f color = sequential_color(static_cast<float>(i) / (samples - 1));
    legend.colors.insert(legend.colors.end(), color.data(), color.data() + 3);
  }
  legend.title = "right: distance from Wobble's step (m)";
  legend.low = "0";
  legend.high =
      two_significant_digits(static_cast<float>(std::max(shown_student_distance_, distance_floor)));
  legend.note = shown_student_distance_ <= distance_floor ? "the same as Wobble's (within 1e-6 m)"
                                                          : "largest distance this step";
  LegendClearance clearance;
  clearance.instrument_column_left = instruments_left_;
  clearance.side_labels = true;
  draw_color_legend(legend, ui_scale, clearance);
}

}  // namespace wobble

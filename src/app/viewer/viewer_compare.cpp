// The viewer's side of the split view: starting and stopping it from the panel and the keys,
// the area the two sides share, and their corner labels. The right side itself is a component
// (right_side.h).
#include <imgui.h>

#include <algorithm>

#include "app/viewer/quantity_colors.h"
#include "app/viewer/viewer.h"
#include "ui/color_legend.h"
#include "ui/side_labels.h"

namespace wobble {

void Viewer::start_split(const CompareSettings& settings) {
  session_.right().start_compare(scene_, host_.simulation(), settings);
  // A shape framed beside the panel (or by the scene's own camera, made for the whole window)
  // would sit off centre in both halves: each half frames it in its middle, from the same
  // direction.
  drawing_.view_camera().centre();
  drawing_.view_camera().frame_next();
  drawing_.add_right_side();
  drawing_.mark_stale();  // the right side's arrays fill at the next refresh or render
}

void Viewer::start_student() {
  session_.right().start_student(scene_, host_.simulation());
  drawing_.add_right_side();
}

void Viewer::stop_split() {
  session_.right().stop();
  drawing_.view_camera().frame_next();  // the whole window again, beside the panel
  session_.right().ask_split(false);
}

void Viewer::apply_split_settings() {
  RightSide& right = session_.right();
  if (right.student()) {  // the student's side stays, with the seed's settings
    right.ask_split(true);
    return;
  }
  if (right.split_asked() && !right.simulation()) {
    start_split(default_compare_settings(host_.simulation().params()));
  }
  if (!right.split_asked() && right.simulation()) stop_split();
  if (right.simulation()) right.apply();
}

void Viewer::draw_overlays(float ui_scale) {
  // The plots' column keeps clear of the panel where it can (a projector's UI scale).
  const PanelPlace place = panel_state_.place();
  const float panel_right = place.shown ? place.x + place.width : 0.0f;
  drawing_.set_plots_left(session_.plots().draw(ui_scale, panel_right));
  if (!host_.batch_started()) session_.update_recording();
  if (!split()) return;
  SideLabels labels;
  labels.left = session_.left_label();
  labels.right = session_.right_label();
  labels.right_warning = session_.right_side_warning();
  const DrawState::SplitArea area = drawing_.split_area(ImGui::GetIO().DisplaySize.x, place);
  labels.area_left = area.left;
  labels.half = area.half;
  draw_side_labels(labels, ui_scale);
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
  const double distance = session_.student_distance();
  legend.high = two_significant_digits(static_cast<float>(std::max(distance, distance_floor)));
  legend.note = distance <= distance_floor ? "the same as Wobble's (within 1e-6 m)"
                                           : "largest distance this step";
  LegendClearance clearance;
  clearance.instrument_column_left = drawing_.plots_left();
  clearance.side_labels = true;
  draw_color_legend(legend, ui_scale, clearance);
}

}  // namespace wobble

// The viewer's side of its instruments (instruments.h): which recordings the simulation keeps.
#include "app/viewer/viewer.h"

namespace wobble {

void Viewer::set_convergence_required(bool required) {
  instruments_.set_convergence_required(required);
  update_recording();
}

void Viewer::update_recording() {
  const bool on = instruments_.wants_convergence();
  if (host_.simulation().records_convergence() != on)
    host_.simulation().set_convergence_recording(on);
}

void Viewer::show_instruments(float ui_scale) {
  // The column keeps clear of the panel where it can (a projector's UI scale).
  const float panel_right = panel_place_.shown ? panel_place_.x + panel_place_.width : 0.0f;
  instruments_left_ = instruments_.draw(ui_scale, panel_right);
  if (!host_.batch_started()) update_recording();
}

}  // namespace wobble

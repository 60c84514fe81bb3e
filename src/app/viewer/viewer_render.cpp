// The viewer's drawing: the draw state's arrays and colours refreshed from the session's
// simulations, and the frame and the legend drawn with what the panel and the mouse hand in.
#include "app/viewer/viewer.h"

namespace wobble {

void Viewer::update_vertex_arrays() {
  drawing_.update_vertex_arrays(host_.simulation(), session_.right_side(),
                                pick_and_drag_.held_vertex(), panel_.paused);
}

void Viewer::update_quantity_colors() {
  drawing_.update_quantity_colors(panel_state_.color_by(), host_.simulation(),
                                  session_.right_side(), panel_.springs);
}

void Viewer::render(int framebuffer_width, int framebuffer_height,
                    const Eigen::Vector2f& window_size, float pixel_ratio,
                    std::optional<float> mark_scale, bool draw) {
  // Between batches a change made since the last refresh is read afresh (a paused drag moves
  // the drawn pin); while a batch runs, the state it started from is drawn.
  if (!host_.batch_started() && drawing_.stale()) update_vertex_arrays();
  update_collider_mesh();
  DrawInputs inputs;
  inputs.width = framebuffer_width;
  inputs.height = framebuffer_height;
  inputs.window = window_size;
  inputs.pixel_ratio = pixel_ratio;
  inputs.mark_scale = mark_scale.value_or(pixel_ratio);
  inputs.draw = draw;
  inputs.panel = panel_state_.place();
  inputs.split = split();
  inputs.layers = panel_state_.layers();
  if (session_.right().student()) inputs.right_colors = &session_.student_colors();
  drawing_.render(inputs, [this](const PointerView& picture, std::vector<unsigned char>& marks) {
    pick_and_drag_.mark(picture, marks);
  });
}

void Viewer::build_legend(float ui_scale) {
  // A student's side is coloured by its distance from Wobble's, and that is what the legend says.
  if (session_.right().student()) {
    draw_student_legend(ui_scale);
    return;
  }
  drawing_.draw_legend(ui_scale, split(), host_.simulation().rest().T.rows() > 0);
}

}  // namespace wobble

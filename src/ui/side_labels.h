#ifndef WOBBLE_UI_SIDE_LABELS_H
#define WOBBLE_UI_SIDE_LABELS_H

#include <string>

namespace wobble {

// What the split view's corners say.
struct SideLabels {
  std::string left, right;    // each side's settings
  std::string right_warning;  // why the right side stopped, or empty
  // The part of the window the two sides share, in ImGui's units: from `left`, two halves of
  // `half` each (what the panel and the plots leave). half <= 0: the whole window.
  float area_left = 0.0f, half = 0.0f;
};

// Writes each half's settings in its bottom-right corner and draws the line between the halves,
// over the scene and under every window (ImGui's background list; between NewFrame and Render).
void draw_side_labels(const SideLabels& labels, float ui_scale);

}  // namespace wobble

#endif

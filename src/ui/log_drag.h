#ifndef WOBBLE_UI_LOG_DRAG_H
#define WOBBLE_UI_LOG_DRAG_H

namespace wobble {

// How much a drag of one pixel multiplies a quantity that spans decades (k, dt, damping, the
// self-collision thickness): 1% a pixel, so 60 pixels take it to 1.01⁶⁰ ≈ 1.82 times. Shift
// makes a pixel ten times as far (1.01¹⁰ ≈ 1.105), Alt a hundredth; Ctrl+click or a double click
// types a value.
constexpr float kLogDragFactorPerPixel = 1.01f;

// ImGui's drag speed (its v_speed) that makes a logarithmic drag over [min, max] multiply the
// value by `factor` per pixel. ImGui moves a logarithmic drag in the ratio
// log(v / lower) / log(max / lower) by v_speed / (max − min) a pixel, where lower is `min`, or
// when `min` is 0 the smallest value `format` shows (0.01 for "%.2f"); so
// v_speed = log(factor) / log(max / lower) · (max − min).
float log_drag_speed(float min, float max, const char* format, float factor);

// A drag box for a value in [min, max] (min ≥ 0, max > min) that moves by a fixed factor per
// pixel, kLogDragFactorPerPixel unless told: the range kept, typed values included. Returns
// whether the value changed. Between ImGui::Begin and End.
bool log_drag(const char* label, float* value, float min, float max, const char* format,
              float factor = kLogDragFactorPerPixel);

}  // namespace wobble

#endif

#include "log_drag.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <cmath>

namespace wobble {

float log_drag_speed(float min, float max, const char* format, float factor) {
  // ImGui's own stand-in for 0 on a log scale: one unit of the last decimal the format shows.
  const float zero = std::pow(0.1f, static_cast<float>(ImParseFormatPrecision(format, 3)));
  const float lower = min < zero ? zero : min;
  return std::log(factor) / std::log(max / lower) * (max - min);
}

bool log_drag(const char* label, float* value, float min, float max, const char* format,
              float factor) {
  // A drag, not a slider: a slider maps its few hundred pixels onto the whole range (six
  // decades for k), and a click on it jumps the value to where the mouse is.
  return ImGui::DragFloat(label, value, log_drag_speed(min, max, format, factor), min, max, format,
                          ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
}

}  // namespace wobble

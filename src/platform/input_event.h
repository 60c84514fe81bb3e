#ifndef WOBBLE_PLATFORM_INPUT_EVENT_H
#define WOBBLE_PLATFORM_INPUT_EVENT_H

namespace wobble {

// One thing the user did, in window coordinates (pixels from the top-left corner, before any
// high-DPI scaling). Key and button codes are GLFW's; the headless mode has no events.
struct InputEvent {
  enum class Type { key_press, button_press, button_release, cursor_move, scroll };
  Type type = Type::cursor_move;
  int code = 0;  // GLFW key for key_press, GLFW mouse button for button_press/button_release
  bool control = false;
  bool shift = false;
  bool alt = false;
  double x = 0.0, y = 0.0;  // cursor position; for scroll, the wheel offsets
};

}  // namespace wobble

#endif

#ifndef WOBBLE_APP_VIEWER_NOTICES_H
#define WOBBLE_APP_VIEWER_NOTICES_H

#include <string>
#include <vector>

namespace wobble {

// The viewer's on-screen confirmations: what F12, Ctrl+S, E or a recording just wrote, and
// where, or why it could not. Each notice shows for `shown_seconds` in a box at the bottom of
// the view, beside the panel, newest last; the panel's notes keep the whole history. A component
// of the viewer: it owns its state and draws itself.
class Notices {
 public:
  static constexpr double shown_seconds = 6.0;
  static constexpr std::size_t most_shown = 4;

  // A notice posted at wall-clock time `now` (s, any steady origin).
  void post(std::string text, double now);
  // The notices still shown at `now`, oldest first (at most most_shown).
  std::vector<std::string> shown(double now) const;
  // ImGui, between NewFrame and Render: the box at the top of the view, between `left` and
  // `right` (ImGui's units: the panel's right edge and the plots' left one), clear of the split
  // view's labels at the bottom; nothing when no notice is shown.
  void draw(double now, float left, float right, float ui_scale, float top = 0.0f) const;

 private:
  struct Notice {
    std::string text;
    double posted = 0.0;
  };
  std::vector<Notice> notices_;
};

// Seconds on the steady clock, the origin fixed for the program's run.
double notice_clock();

}  // namespace wobble

#endif

#ifndef WOBBLE_APP_VIEWER_FRAME_METERS_H
#define WOBBLE_APP_VIEWER_FRAME_METERS_H

#include "app/viewer/moving_median.h"
#include "app/viewer/real_time_meter.h"
#include "ui/control_panel.h"

namespace wobble {

// What the panel's stats footer says of the frames themselves, the same in the window
// (run_window.cpp) and the browser (app/web/run_browser.cpp): the frame rate, the UI's own work
// per frame, and how the simulation keeps up with the wall clock.
struct FrameMeters {
  RealTimeMeter real_time;
  MovingMedian frame_ms;     // from one frame's start to the next (ms)
  MovingMedian ui_work_ms;   // a frame's own work, poll to the picture drawn (ms)
  double last_frame = -1.0;  // when the last frame started (s); < 0 before the first
  long frames = 0;           // the frames started, the one drawing included

  // A frame starts at `now` (s, on the loop's clock).
  void start_frame(double now) {
    ++frames;
    if (last_frame >= 0.0) frame_ms.add(static_cast<float>(1e3 * (now - last_frame)));
    last_frame = now;
  }
  // The frame that started at `now` is drawn, at `done` (s).
  void end_frame(double now, double done) {
    ui_work_ms.add(static_cast<float>(1e3 * (done - now)));
  }
  // The figures Viewer::build_ui shows that come from the wall clock.
  PanelStats timings() const {
    PanelStats timings;
    timings.fps = frame_ms.median() > 0.0f ? 1e3f / frame_ms.median() : 0.0f;
    timings.ui_frame_ms = ui_work_ms.median();
    timings.real_time_factor = static_cast<float>(real_time.real_time_factor());
    timings.steps_per_second = static_cast<float>(real_time.steps_per_second());
    return timings;
  }
};

}  // namespace wobble

#endif

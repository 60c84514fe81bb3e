#ifndef WOBBLE_APP_VIEWER_STEP_PACER_H
#define WOBBLE_APP_VIEWER_STEP_PACER_H

namespace wobble {

// How many steps the window's simulation takes before the next displayed frame, in "real time"
// mode: as many as keep the simulated clock with the wall clock, but no more than fit in one
// frame (from the recent step time), and at most max_steps_per_frame. When a step is slower than
// real time that is one a frame and the motion is slow; the real-time factor says so. Time the
// simulation could not keep up with is dropped, never made up later in a burst. Knows nothing
// of clocks: fed made-up times in tests.
class StepPacer {
 public:
  static constexpr int max_steps_per_frame = 16;

  // The steps to start at wall time `now` (s, any origin, non-decreasing) for time step `dt`
  // (s), given the recent wall time of one step (s, 0 when not known) and the time a displayed
  // frame may take (s). 0 while the simulated clock is ahead of the wall clock.
  int steps_due(double now, double dt, double step_seconds, double frame_seconds);
  // Start again from the next call: after a pause, a reset, a new scene or a new dt.
  void restart() { started_ = false; }

 private:
  bool started_ = false;
  double origin_ = 0.0;  // wall time at which the simulated clock read `taken_ = 0`
  long taken_ = 0;       // steps handed out since origin_
};

}  // namespace wobble

#endif

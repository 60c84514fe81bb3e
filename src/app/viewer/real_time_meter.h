#ifndef WOBBLE_APP_VIEWER_REAL_TIME_METER_H
#define WOBBLE_APP_VIEWER_REAL_TIME_METER_H

#include <deque>

namespace wobble {

// How fast the simulation runs against the wall clock, over about the last second: the real-time
// factor (simulated seconds per wall-clock second; below 1 the motion on screen is slow motion)
// and steps per second. Fed once a frame; knows nothing of the clock or the simulation itself,
// so it can be tested with made-up times.
class RealTimeMeter {
 public:
  static constexpr double window_seconds = 1.0;  // wall-clock span the figures cover

  // One frame's sample: the wall-clock time (s, any origin, non-decreasing), the simulation's
  // time (s) and its step count. A simulated time or step count that goes backwards (a reset, a
  // new scene) starts the measurement again.
  void record(double wall_seconds, double simulated_seconds, long steps);

  // Over the samples of the last window_seconds; 0 until two samples span some time.
  double real_time_factor() const;
  double steps_per_second() const;

 private:
  struct Sample {
    double wall, simulated;
    long steps;
  };
  double wall_span() const;
  std::deque<Sample> samples_;
};

}  // namespace wobble

#endif

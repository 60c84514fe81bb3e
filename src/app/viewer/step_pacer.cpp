#include "app/viewer/step_pacer.h"

#include <algorithm>
#include <cmath>

namespace wobble {

int StepPacer::steps_due(double now, double dt, double step_seconds, double frame_seconds) {
  if (!(dt > 0.0)) return 1;
  if (!started_) {
    started_ = true;
    origin_ = now;
    taken_ = 0;
  }
  // Step n (from 0) covers simulated time up to (n + 1)·dt; it is due once the wall clock passed
  // n·dt, so the first step starts at once. (A millionth of a step of slack keeps frames that are
  // whole multiples of dt from taking 3 steps, then 5, by rounding.)
  const double behind = std::floor((now - origin_) / dt + 1e-6) + 1.0 - static_cast<double>(taken_);
  if (behind < 1.0) return 0;
  // As many as fit in a frame, one at least.
  const int fit = step_seconds > 0.0
                      ? static_cast<int>(std::clamp(std::floor(frame_seconds / step_seconds), 1.0,
                                                    static_cast<double>(max_steps_per_frame)))
                      : 1;
  const double take = std::min(behind, static_cast<double>(fit));
  // What is left behind is dropped: the clock's origin moves so that the wall clock is only the
  // steps taken now ahead.
  if (behind > take) origin_ += (behind - take) * dt;
  taken_ += static_cast<long>(take);
  return static_cast<int>(take);
}

}  // namespace wobble

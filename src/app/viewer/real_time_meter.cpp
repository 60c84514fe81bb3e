#include "app/viewer/real_time_meter.h"

namespace wobble {

void RealTimeMeter::record(double wall_seconds, double simulated_seconds, long steps) {
  if (!samples_.empty() &&
      (simulated_seconds < samples_.back().simulated || steps < samples_.back().steps)) {
    samples_.clear();
  }
  samples_.push_back({wall_seconds, simulated_seconds, steps});
  // The oldest sample goes only once the next one is itself a window old, so the figures span a
  // little more than window_seconds rather than a little less.
  while (samples_.size() > 2 && wall_seconds - samples_[1].wall >= window_seconds)
    samples_.pop_front();
}

double RealTimeMeter::wall_span() const {
  return samples_.size() < 2 ? 0.0 : samples_.back().wall - samples_.front().wall;
}

double RealTimeMeter::real_time_factor() const {
  const double span = wall_span();
  if (span <= 0.0) return 0.0;
  return (samples_.back().simulated - samples_.front().simulated) / span;
}

double RealTimeMeter::steps_per_second() const {
  const double span = wall_span();
  if (span <= 0.0) return 0.0;
  return static_cast<double>(samples_.back().steps - samples_.front().steps) / span;
}

}  // namespace wobble

#ifndef WOBBLE_SIM_INSTRUMENTS_STOPWATCH_H
#define WOBBLE_SIM_INSTRUMENTS_STOPWATCH_H

#include <chrono>

namespace wobble {

// Wall-clock milliseconds since it was made: the step's timings.
class Stopwatch {
 public:
  double milliseconds() const {
    return std::chrono::duration<double, std::milli>(Clock::now() - start_).count();
  }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_ = Clock::now();
};

}  // namespace wobble

#endif

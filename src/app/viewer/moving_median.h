#ifndef WOBBLE_APP_VIEWER_MOVING_MEDIAN_H
#define WOBBLE_APP_VIEWER_MOVING_MEDIAN_H

#include <array>

namespace wobble {

// The median of the last `capacity` values added: what the panel shows for step times, so a
// single slow step (a page fault, a busy neighbour) does not make the number jump from 2 to
// 800 ms and back. Fixed storage: adding allocates nothing.
class MovingMedian {
 public:
  static constexpr int capacity = 15;
  void add(float value);
  // 0 before the first value.
  float median() const;
  void clear() { count_ = next_ = 0; }

 private:
  std::array<float, capacity> values_{};
  int count_ = 0, next_ = 0;
};

}  // namespace wobble

#endif

#include "app/viewer/moving_median.h"

#include <algorithm>

namespace wobble {

void MovingMedian::add(float value) {
  values_[next_] = value;
  next_ = (next_ + 1) % capacity;
  count_ = std::min(count_ + 1, capacity);
}

float MovingMedian::median() const {
  if (count_ == 0) return 0.0f;
  std::array<float, capacity> sorted = values_;
  std::nth_element(sorted.begin(), sorted.begin() + count_ / 2, sorted.begin() + count_);
  return sorted[count_ / 2];
}

}  // namespace wobble

#include "pin_mark_sizes.h"

#include <algorithm>
#include <cmath>

namespace wobble {

namespace {

std::uint64_t cell_key(std::int64_t column, std::int64_t row) {
  return (static_cast<std::uint64_t>(column) << 32) ^ static_cast<std::uint32_t>(row);
}

}  // namespace

const std::vector<float>& PinMarkSizes::compute(const float* screen, int pin_count,
                                                const PinMarkRule& rule) {
  diameters_.assign(pin_count, rule.largest);
  const float reach = rule.largest / rule.spacing_share;
  if (pin_count < 2 || !(reach > 0.0f)) return diameters_;
  const auto cell_of = [&](int i, int axis) {
    return static_cast<std::int64_t>(std::floor(screen[2 * i + axis] / reach));
  };
  cells_.resize(pin_count);
  for (int i = 0; i < pin_count; ++i)
    cells_[i] = {cell_key(cell_of(i, 0), cell_of(i, 1)), i};
  std::sort(cells_.begin(), cells_.end());
  for (int i = 0; i < pin_count; ++i) {
    float nearest = reach;
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const std::uint64_t key = cell_key(cell_of(i, 0) + dx, cell_of(i, 1) + dy);
        auto at = std::lower_bound(cells_.begin(), cells_.end(), std::make_pair(key, -1));
        for (; at != cells_.end() && at->first == key; ++at) {
          const int j = at->second;
          if (j == i) continue;
          nearest = std::min(nearest, std::hypot(screen[2 * j] - screen[2 * i],
                                                 screen[2 * j + 1] - screen[2 * i + 1]));
        }
      }
    }
    diameters_[i] = std::min(rule.largest, std::max(rule.smallest, rule.spacing_share * nearest));
  }
  return diameters_;
}

}  // namespace wobble

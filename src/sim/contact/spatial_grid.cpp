#include "sim/contact/spatial_grid.h"

#include <algorithm>

namespace wobble {

int SpatialGrid::level_for(const Eigen::AlignedBox3f& box) const {
  if (box.isEmpty() || !box.min().allFinite() || !box.max().allFinite()) return -1;
  // Centres beyond int cell coordinates on level 0 go up a level until they fit.
  const double extent = std::max<double>(box.sizes().maxCoeff(),
                                         box.center().cast<double>().cwiseAbs().maxCoeff() * 1e-9);
  int level = 0;
  double size = cell_;
  while (extent > size && level + 1 < max_levels) {
    size *= 4.0;
    ++level;
  }
  return level;
}

void SpatialGrid::lay_out(const std::array<std::size_t, max_levels>& counts) {
  double size = cell_;
  std::size_t slot_total = 0;
  int entry_total = 0;
  for (int k = 0; k < max_levels; ++k, size *= 4.0) {
    Level& level = levels_[k];
    level.cell = size;
    level.slots = 1;
    // A level with no box keeps one slot (looked at by no query).
    while (counts[k] > 0 && level.slots < 2 * counts[k] + 1)
      level.slots *= 2;
    level.first_slot = slot_total;
    slot_total += level.slots + 1;
    level.first_entry = entry_total;
    level.count = static_cast<int>(counts[k]);
    entry_total += level.count;
  }
  start_.assign(slot_total, 0);
  entries_.resize(entry_total);
}

std::size_t SpatialGrid::memory_bytes() const {
  return level_of_.capacity() + start_.capacity() * sizeof(int) +
         entries_.capacity() * sizeof(Entry);
}

}  // namespace wobble

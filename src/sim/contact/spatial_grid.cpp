#include "sim/contact/spatial_grid.h"

#include <cmath>

namespace wobble {

bool SpatialGrid::cell_range(const Eigen::AlignedBox3d& box, Eigen::Array3i& low,
                             Eigen::Array3i& high) const {
  const Eigen::Array3d lo = (box.min().array() / cell_).floor();
  const Eigen::Array3d hi = (box.max().array() / cell_).floor();
  // Also catches a box too far out for int cell coordinates, or a NaN.
  if (!((hi - lo + 1.0).prod() <= static_cast<double>(max_cells_per_box))) return false;
  if (!(lo.abs().maxCoeff() < 1e9 && hi.abs().maxCoeff() < 1e9)) return false;
  low = lo.cast<int>();
  high = hi.cast<int>();
  return true;
}

std::uint32_t SpatialGrid::cell_slot(int x, int y, int z) const {
  // Three large primes, multiplied and mixed: neighbouring cells land in unrelated slots.
  const std::uint64_t h = static_cast<std::uint64_t>(static_cast<std::int64_t>(x)) * 73856093u ^
                          static_cast<std::uint64_t>(static_cast<std::int64_t>(y)) * 19349663u ^
                          static_cast<std::uint64_t>(static_cast<std::int64_t>(z)) * 83492791u;
  return static_cast<std::uint32_t>(h ^ (h >> 29)) & (slots_ - 1);
}

void SpatialGrid::build(const std::vector<Eigen::AlignedBox3d>& boxes) {
  boxes_ = &boxes;
  box_count_ = boxes.size();
  is_large_.assign(boxes.size(), 0);
  // About twice as many slots as filed entries (a box in several cells is several entries), so
  // that few cells share a slot: a shared slot's boxes are all tested against each other.
  std::size_t entries = 0;
  for (const Eigen::AlignedBox3d& box : boxes) {
    Eigen::Array3i low, high;
    if (cell_range(box, low, high)) entries += static_cast<std::size_t>((high - low + 1).prod());
  }
  slots_ = 1;
  while (slots_ < 2 * entries + 1)
    slots_ *= 2;
  start_.assign(slots_ + 1, 0);
  large_.clear();
  // Two passes of a counting sort: how many boxes each slot gets, then the boxes.
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      for (std::uint32_t s = 0; s < slots_; ++s)
        start_[s + 1] += start_[s];
      items_.resize(start_[slots_]);
      entries_.resize(start_[slots_]);
      fill_.assign(start_.begin(), start_.end() - 1);
    }
    for (std::size_t id = 0; id < boxes.size(); ++id) {
      Eigen::Array3i low, high;
      if (!cell_range(boxes[id], low, high)) {
        if (pass == 0) {
          large_.push_back(static_cast<int>(id));
          is_large_[id] = 1;
        }
        continue;
      }
      for (int x = low.x(); x <= high.x(); ++x) {
        for (int y = low.y(); y <= high.y(); ++y) {
          for (int z = low.z(); z <= high.z(); ++z) {
            const std::uint32_t slot = cell_slot(x, y, z);
            if (pass == 0) {
              ++start_[slot + 1];
            } else {
              entries_[fill_[slot]] = Entry{boxes[id], low, static_cast<int>(id)};
              items_[fill_[slot]++] = static_cast<int>(id);
            }
          }
        }
      }
    }
  }
}

}  // namespace wobble

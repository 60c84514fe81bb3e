#include "sim/contact/spatial_grid.h"

#include <algorithm>

namespace wobble {

void SpatialGrid::build(const std::vector<Eigen::AlignedBox3d>& boxes, double cell) {
  build(
      static_cast<int>(boxes.size()), [&](int id) { return boxes[id]; }, cell);
}

void SpatialGrid::build(int count, const std::function<Eigen::AlignedBox3d(int)>& box_of,
                        double cell) {
  cell_ = cell > 0.0 && std::isfinite(cell) ? cell : 1.0;
  count = std::max(count, 0);
  level_of_.resize(count);
  std::array<std::size_t, max_levels> counts{};
  for (int id = 0; id < count; ++id) {
    const Eigen::AlignedBox3d box = box_of(id);
    level_of_[id] = -1;
    if (box.isEmpty() || !box.min().allFinite() || !box.max().allFinite()) continue;
    // Centres beyond int cell coordinates on level 0 go up a level until they fit.
    const double extent =
        std::max(box.sizes().maxCoeff(), box.center().cwiseAbs().maxCoeff() * 1e-9);
    int level = 0;
    double size = cell_;
    while (extent > size && level + 1 < max_levels) {
      size *= 4.0;
      ++level;
    }
    level_of_[id] = static_cast<std::int8_t>(level);
    ++counts[level];
  }
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
  // A counting sort per level: how many boxes each slot gets, their running sums (where each
  // slot ends), then the boxes from the last id down, each slot's end moving back to its start.
  const auto slot_of = [&](const Eigen::AlignedBox3d& box, const Level& level, Eigen::Array3i& c) {
    c = ((box.center().array()) / level.cell).floor().cast<int>();
    return level.first_slot + cell_slot(c.x(), c.y(), c.z(), level.slots);
  };
  Eigen::Array3i c;
  for (int id = 0; id < count; ++id) {
    if (level_of_[id] >= 0) ++start_[slot_of(box_of(id), levels_[level_of_[id]], c)];
  }
  for (const Level& level : levels_) {
    int* start = start_.data() + level.first_slot;
    start[0] += level.first_entry;
    for (std::uint32_t s = 1; s < level.slots; ++s)
      start[s] += start[s - 1];
    start[level.slots] = level.first_entry + level.count;
  }
  for (int id = count - 1; id >= 0; --id) {
    if (level_of_[id] < 0) continue;
    const std::size_t slot = slot_of(box_of(id), levels_[level_of_[id]], c);
    entries_[--start_[slot]] = Entry{id, c.x(), c.y(), c.z()};
  }
}

std::size_t SpatialGrid::memory_bytes() const {
  return level_of_.capacity() + start_.capacity() * sizeof(int) +
         entries_.capacity() * sizeof(Entry);
}

}  // namespace wobble

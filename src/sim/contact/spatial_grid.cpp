#include "sim/contact/spatial_grid.h"

#include <algorithm>

namespace wobble {

void SpatialGrid::build(const std::vector<Eigen::AlignedBox3d>& boxes, double cell) {
  cell_ = cell > 0.0 && std::isfinite(cell) ? cell : 1.0;
  level_of_.resize(boxes.size());
  std::array<std::size_t, max_levels> counts{};
  for (std::size_t id = 0; id < boxes.size(); ++id) {
    const Eigen::AlignedBox3d& box = boxes[id];
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
  for (int k = 0; k < max_levels; ++k, size *= 4.0) {
    Level& level = levels_[k];
    level.cell = size;
    level.slots = 1;
    while (level.slots < 2 * counts[k] + 1)
      level.slots *= 2;
    level.start.assign(level.slots + 1, 0);
    level.entries.resize(counts[k]);
  }
  // Two passes of a counting sort per level: how many boxes each slot gets, then the boxes.
  const auto centre_cell = [&](const Eigen::AlignedBox3d& box, const Level& level) {
    return Eigen::Array3i(((box.center().array()) / level.cell).floor().cast<int>());
  };
  for (std::size_t id = 0; id < boxes.size(); ++id) {
    if (level_of_[id] < 0) continue;
    Level& level = levels_[level_of_[id]];
    const Eigen::Array3i c = centre_cell(boxes[id], level);
    ++level.start[cell_slot(c.x(), c.y(), c.z(), level.slots) + 1];
  }
  for (int k = 0; k < max_levels; ++k) {
    Level& level = levels_[k];
    for (std::uint32_t s = 0; s < level.slots; ++s)
      level.start[s + 1] += level.start[s];
    if (counts[k] > 0) level.fill.assign(level.start.begin(), level.start.end() - 1);
  }
  for (std::size_t id = 0; id < boxes.size(); ++id) {
    if (level_of_[id] < 0) continue;
    Level& level = levels_[level_of_[id]];
    const Eigen::Array3i c = centre_cell(boxes[id], level);
    const std::uint32_t slot = cell_slot(c.x(), c.y(), c.z(), level.slots);
    level.entries[level.fill[slot]++] = Entry{boxes[id], static_cast<int>(id), c.x(), c.y(), c.z()};
  }
}

std::size_t SpatialGrid::memory_bytes() const {
  std::size_t bytes = level_of_.capacity();
  for (const Level& level : levels_)
    bytes += (level.start.capacity() + level.fill.capacity()) * sizeof(int) +
             level.entries.capacity() * sizeof(Entry);
  return bytes;
}

}  // namespace wobble

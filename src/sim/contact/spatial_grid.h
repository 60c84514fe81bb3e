#ifndef WOBBLE_SIM_CONTACT_SPATIAL_GRID_H
#define WOBBLE_SIM_CONTACT_SPATIAL_GRID_H

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

namespace wobble {

// Boxes filed for finding which of them a query box overlaps, rebuilt from scratch whenever the
// boxes move. A hierarchy of uniform grids: level k has cells of side cell·4ᵏ, and each box is
// filed once, at the cell of its centre, on the first level whose cell is at least as large as
// the box. So a box that overlaps a query has its centre within half a cell of the query box on
// its level, and a query looks at the few cells around it on each level in use. Each level is a
// counting sort of its boxes' ids into a hash table of about twice as many slots (no bounds, no
// allocation once the buffers have grown). The grid keeps no copy of the boxes: the caller
// holds them (or computes them) and gives them to each query as box_of(id).
//
// Bounded by design: memory is O(boxes) whatever their sizes and places (16 bytes a box, and
// two ints a slot); a build costs O(boxes); a query costs O(the boxes whose cells it looks at),
// and never more cells than a level has boxes (a query box large for a level looks at that
// level's boxes one by one instead). Boxes that are empty or not finite are not filed.
class SpatialGrid {
 public:
  static constexpr int max_levels = 16;

  // Files boxes 0..count−1, box id being box_of(id); level 0's cell is `cell` (m).
  void build(int count, const std::function<Eigen::AlignedBox3d(int)>& box_of, double cell);
  void build(const std::vector<Eigen::AlignedBox3d>& boxes, double cell);
  double cell() const { return cell_; }

  // Calls visit(id) exactly once for every filed box that overlaps `box` (closed boxes:
  // touching counts), until visit returns false. box_of(id) must give the boxes of the last
  // build. Safe to call from several threads at once between builds.
  template <typename BoxOf, typename Visit>
  void for_each_overlapping(const Eigen::AlignedBox3d& box, const BoxOf& box_of,
                            Visit&& visit) const {
    if (box.isEmpty()) return;
    for (const Level& level : levels_) {
      if (level.count == 0) continue;
      const double half = 0.5 * level.cell;
      const Eigen::Array3d lo = ((box.min().array() - half) / level.cell).floor();
      const Eigen::Array3d hi = ((box.max().array() + half) / level.cell).floor();
      const double cells = (hi - lo + 1.0).prod();
      if (!(cells <= static_cast<double>(level.count)) ||
          !(lo.abs().maxCoeff() < 1e9 && hi.abs().maxCoeff() < 1e9)) {
        // Cheaper (or only possible) to look at every box of the level once.
        for (int s = level.first_entry; s < level.first_entry + level.count; ++s) {
          const int id = entries_[s].id;
          if (box.intersects(box_of(id)) && !visit(id)) return;
        }
        continue;
      }
      const Eigen::Array3i low = lo.cast<int>(), high = hi.cast<int>();
      for (int x = low.x(); x <= high.x(); ++x) {
        for (int y = low.y(); y <= high.y(); ++y) {
          for (int z = low.z(); z <= high.z(); ++z) {
            const std::size_t slot = level.first_slot + cell_slot(x, y, z, level.slots);
            for (int s = start_[slot]; s < start_[slot + 1]; ++s) {
              const Entry& entry = entries_[s];
              // The slot holds every cell that hashes to it: only this cell's boxes.
              if (entry.x != x || entry.y != y || entry.z != z) continue;
              if (box.intersects(box_of(entry.id)) && !visit(entry.id)) return;
            }
          }
        }
      }
    }
  }
  // The same with the boxes in a vector.
  template <typename Visit>
  void for_each_overlapping(const Eigen::AlignedBox3d& box,
                            const std::vector<Eigen::AlignedBox3d>& boxes, Visit&& visit) const {
    for_each_overlapping(
        box, [&](int id) -> const Eigen::AlignedBox3d& { return boxes[id]; }, visit);
  }

  // Memory held by the grid's buffers (bytes).
  std::size_t memory_bytes() const;

 private:
  struct Entry {
    int id;
    int x, y, z;  // the cell of the box's centre
  };
  // The levels share two buffers (each level its own range in them), so that memory follows
  // the boxes filed now rather than the most each level ever held.
  struct Level {
    double cell = 1.0;
    std::uint32_t slots = 1;         // a power of two
    std::size_t first_slot = 0;      // its slots + 1 starts in start_
    int first_entry = 0, count = 0;  // its range of entries_
  };
  static std::uint32_t cell_slot(int x, int y, int z, std::uint32_t slots) {
    // Three large primes, multiplied and mixed: neighbouring cells land in unrelated slots.
    const std::uint64_t h = static_cast<std::uint64_t>(static_cast<std::int64_t>(x)) * 73856093u ^
                            static_cast<std::uint64_t>(static_cast<std::int64_t>(y)) * 19349663u ^
                            static_cast<std::uint64_t>(static_cast<std::int64_t>(z)) * 83492791u;
    return static_cast<std::uint32_t>(h ^ (h >> 29)) & (slots - 1);
  }

  double cell_ = 1.0;
  std::array<Level, max_levels> levels_;
  std::vector<int> start_;      // per level, slots + 1: where each slot's entries begin in entries_
  std::vector<Entry> entries_;  // level by level, slot by slot, ascending ids within a slot
  std::vector<std::int8_t> level_of_;  // #boxes: its level, −1 when not filed
};

}  // namespace wobble

#endif

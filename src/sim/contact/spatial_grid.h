#ifndef WOBBLE_SIM_CONTACT_SPATIAL_GRID_H
#define WOBBLE_SIM_CONTACT_SPATIAL_GRID_H

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace wobble {

// Boxes filed for finding which of them a query box overlaps, rebuilt from scratch whenever the
// boxes move. A hierarchy of uniform grids: level k has cells of side cell·4ᵏ, and each box is
// filed once, at the cell of its centre, on the first level whose cell is at least as large as
// the box. So a box that overlaps a query has its centre within half a cell of the query box on
// its level, and a query looks at the few cells around it on each level in use. Each level is a
// counting sort of its boxes into a hash table of about twice as many slots (no bounds, no
// allocation once the buffers have grown).
//
// The grid keeps each box in single precision, rounded outwards (outward()), and rounds a
// query box outwards too: a query may also visit a box that only comes within a float's rounding
// of it (about 10⁻⁷ of the coordinates), never misses one that overlaps, and a box costs 40
// bytes instead of 64.
//
// Bounded by design: memory is O(boxes) whatever their sizes and places (one entry a box, and an
// int for each of about two slots a box); a build costs O(boxes); a query costs O(the boxes
// whose cells it looks at), and never more cells than a level has boxes (a query box large for a
// level looks at that level's boxes one by one instead). Boxes that are empty or not finite
// (or beyond float's range, 3·10³⁸) are not filed.
class SpatialGrid {
 public:
  static constexpr int max_levels = 16;

  // The smallest box in single precision holding `box` (empty stays empty).
  static Eigen::AlignedBox3f outward(const Eigen::AlignedBox3d& box) {
    Eigen::AlignedBox3f rounded;
    if (box.isEmpty()) return rounded;
    for (int axis = 0; axis < 3; ++axis) {
      rounded.min()(axis) = below(box.min()(axis));
      rounded.max()(axis) = above(box.max()(axis));
    }
    return rounded;
  }

  // A float at or below x, and one at or above it: x moved out by two of float's roundings
  // (relative, and absolute near 0) before rounding to nearest, cheaper than std::nextafter.
  // Beyond float's range: an infinity (a box with one is not filed).
  static float below(double x) {
    const double moved = x - std::abs(x) * 0x1p-22 - 0x1p-120;
    return moved >= -max_float ? static_cast<float>(moved) : -infinite_float;
  }
  static float above(double x) {
    const double moved = x + std::abs(x) * 0x1p-22 + 0x1p-120;
    return moved <= max_float ? static_cast<float>(moved) : infinite_float;
  }
  static constexpr double max_float = std::numeric_limits<float>::max();
  static constexpr float infinite_float = std::numeric_limits<float>::infinity();

  // Files boxes 0..count−1, box id being box_of(id) (an Eigen::AlignedBox3d, asked for a few
  // times a build); level 0's cell is `cell` (m).
  template <typename BoxOf>
  void build(int count, const BoxOf& box_of, double cell);
  void build(const std::vector<Eigen::AlignedBox3d>& boxes, double cell) {
    build(
        static_cast<int>(boxes.size()), [&](int id) { return boxes[id]; }, cell);
  }
  double cell() const { return cell_; }

  // Calls visit(id) (or visit(id, filed) with the box as filed, in single precision) exactly
  // once for every filed box that overlaps `box` (closed boxes: touching counts), and perhaps
  // for some that come within rounding of it (see above), until visit returns false. Safe to
  // call from several threads at once between builds.
  template <typename Visit>
  void for_each_overlapping(const Eigen::AlignedBox3d& box, Visit&& visit) const {
    if (box.isEmpty() || box.min().hasNaN() || box.max().hasNaN()) return;
    const Eigen::AlignedBox3f query = outward(box);
    const auto call = [&](const Entry& entry) {
      if constexpr (std::is_invocable_v<Visit, int, const Eigen::AlignedBox3f&>) {
        return visit(entry.id, entry.box);
      } else {
        return visit(entry.id);
      }
    };
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
          const Entry& entry = entries_[s];
          if (query.intersects(entry.box) && !call(entry)) return;
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
              if (query.intersects(entry.box) && !call(entry)) return;
            }
          }
        }
      }
    }
  }

  // The boxes filed, in the grid's order: how many, and the k-th's id and box as filed.
  int filed_count() const { return static_cast<int>(entries_.size()); }
  std::pair<int, Eigen::AlignedBox3f> filed(int k) const {
    return {entries_[k].id, entries_[k].box};
  }

  // Memory held by the grid's buffers (bytes).
  std::size_t memory_bytes() const;

 private:
  struct Entry {
    Eigen::AlignedBox3f box;
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
  // The level a box goes on, or −1 for none; and the slots of its centre's cell there.
  int level_for(const Eigen::AlignedBox3f& box) const;
  std::size_t slot_for(const Eigen::AlignedBox3f& box, int level, Eigen::Array3i& cell) const {
    const Level& on = levels_[level];
    cell = (box.center().cast<double>().array() / on.cell).floor().cast<int>();
    return on.first_slot + cell_slot(cell.x(), cell.y(), cell.z(), on.slots);
  }
  // Sizes the levels and start_ from counts[k] boxes on level k.
  void lay_out(const std::array<std::size_t, max_levels>& counts);

  double cell_ = 1.0;
  std::array<Level, max_levels> levels_;
  std::vector<int> start_;      // per level, slots + 1: where each slot's entries begin in entries_
  std::vector<Entry> entries_;  // level by level, slot by slot, ascending ids within a slot
  std::vector<std::int8_t> level_of_;  // #boxes: its level, −1 when not filed
};

template <typename BoxOf>
void SpatialGrid::build(int count, const BoxOf& box_of, double cell) {
  cell_ = cell > 0.0 && std::isfinite(cell) ? cell : 1.0;
  count = std::max(count, 0);
  level_of_.resize(count);
  std::array<std::size_t, max_levels> counts{};
  for (int id = 0; id < count; ++id) {
    const int level = level_for(outward(box_of(id)));
    level_of_[id] = static_cast<std::int8_t>(level);
    if (level >= 0) ++counts[level];
  }
  lay_out(counts);
  // A counting sort per level: how many boxes each slot gets, their running sums (where each
  // slot ends), then the boxes from the last id down, each slot's end moving back to its start.
  Eigen::Array3i c;
  for (int id = 0; id < count; ++id) {
    if (level_of_[id] >= 0) ++start_[slot_for(outward(box_of(id)), level_of_[id], c)];
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
    const Eigen::AlignedBox3f box = outward(box_of(id));
    const std::size_t slot = slot_for(box, level_of_[id], c);
    entries_[--start_[slot]] = Entry{box, id, c.x(), c.y(), c.z()};
  }
}

}  // namespace wobble

#endif

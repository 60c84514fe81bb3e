#ifndef WOBBLE_SIM_CONTACT_SPATIAL_GRID_H
#define WOBBLE_SIM_CONTACT_SPATIAL_GRID_H

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

namespace wobble {

// A uniform grid of boxes for finding which boxes a query box may overlap, rebuilt from scratch
// whenever the boxes move (a counting sort: two passes over the boxes, no allocation once the
// buffers have grown). Cells are cubes of side `cell`; a cell's coordinates are hashed into a
// table of about twice as many slots as boxes, so the grid has no bounds. A box covering more
// than max_cells_per_box cells (one that moved far in a step) goes on a list every query visits.
class SpatialGrid {
 public:
  static constexpr std::int64_t max_cells_per_box = 512;

  explicit SpatialGrid(double cell = 1.0) : cell_(cell) {}
  double cell() const { return cell_; }

  // Files each of `boxes` (#boxes, ids 0..#boxes−1) under the cells it covers. `boxes` must
  // outlive the queries.
  void build(const std::vector<Eigen::AlignedBox3d>& boxes);

  // Calls visit(i, j), i < j, once for every two boxes that overlap, the large ones included:
  // each slot's boxes against each other, a pair taken only in the first cell both cover.
  template <typename Visit>
  void for_each_overlapping_pair(Visit&& visit) const {
    for (std::uint32_t slot = 0; slot < slots_; ++slot) {
      for (int s = start_[slot]; s < start_[slot + 1]; ++s) {
        for (int t = s + 1; t < start_[slot + 1]; ++t) {
          const Entry& a = entries_[s];
          const Entry& b = entries_[t];
          if (a.id == b.id || !a.box.intersects(b.box)) continue;
          // The first cell both cover; the pair is taken in its slot only.
          const Eigen::Array3i first = a.low.max(b.low);
          if (cell_slot(first.x(), first.y(), first.z()) != slot) continue;
          visit(std::min(a.id, b.id), std::max(a.id, b.id));
        }
      }
    }
    for (std::size_t l = 0; l < large_.size(); ++l) {
      const Eigen::AlignedBox3d& box = (*boxes_)[large_[l]];
      for (int id = 0; id < static_cast<int>(box_count_); ++id) {
        if (id == large_[l] || !box.intersects((*boxes_)[id])) continue;
        // Two large boxes: once, from the lower id's turn.
        if (is_large_[id] && id < large_[l]) continue;
        visit(std::min(id, large_[l]), std::max(id, large_[l]));
      }
    }
  }

  // Calls visit(id) for every box filed under a cell that `box` covers, and every large box. An
  // id can come more than once (a box in several of the cells); the caller tells them apart.
  template <typename Visit>
  void for_each_candidate(const Eigen::AlignedBox3d& box, Visit&& visit) const {
    Eigen::Array3i low, high;
    if (!cell_range(box, low, high)) {
      for (int id = 0; id < static_cast<int>(box_count_); ++id)
        visit(id);
      return;
    }
    for (int x = low.x(); x <= high.x(); ++x) {
      for (int y = low.y(); y <= high.y(); ++y) {
        for (int z = low.z(); z <= high.z(); ++z) {
          const std::uint32_t slot = cell_slot(x, y, z);
          for (int s = start_[slot]; s < start_[slot + 1]; ++s)
            visit(items_[s]);
        }
      }
    }
    for (const int id : large_)
      visit(id);
  }

 private:
  // The cells a box covers; false when they are more than max_cells_per_box.
  bool cell_range(const Eigen::AlignedBox3d& box, Eigen::Array3i& low, Eigen::Array3i& high) const;
  std::uint32_t cell_slot(int x, int y, int z) const;

  // A box as filed: its id, the box and its lowest cell.
  struct Entry {
    Eigen::AlignedBox3d box;
    Eigen::Array3i low;
    int id;
  };

  double cell_;
  const std::vector<Eigen::AlignedBox3d>* boxes_ = nullptr;  // those of the last build
  std::vector<Entry> entries_;                               // by slot, as items_
  std::vector<char> is_large_;
  std::size_t box_count_ = 0;
  std::uint32_t slots_ = 1;  // a power of two
  std::vector<int> start_;   // slots_ + 1: where each slot's ids begin in items_
  std::vector<int> items_, large_;
  std::vector<int> fill_;
};

}  // namespace wobble

#endif

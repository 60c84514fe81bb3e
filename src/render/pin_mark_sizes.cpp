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

void PinMarks::take(const unsigned char* marks, const float* positions) {
  pin_vertices_.clear();
  pin_positions_.clear();
  const int vertex_count = static_cast<int>(vertex_diameters_.size());
  for (int i = 0; i < vertex_count; ++i) {
    if (marks[i] == 0) continue;
    pin_vertices_.push_back(i);
    pin_positions_.insert(pin_positions_.end(), positions + 3 * i, positions + 3 * i + 3);
  }
}

const std::vector<float>& PinMarks::size(const Eigen::Matrix4f& view_projection, int width,
                                         int height, float pixel_ratio) {
  const int pin_count = static_cast<int>(pin_vertices_.size());
  if (pin_count == 0) return vertex_diameters_;
  pin_screen_.clear();
  pins_in_front_.clear();
  for (int p = 0; p < pin_count; ++p) {
    const Eigen::Vector4f clip =
        view_projection * Eigen::Vector4f(pin_positions_[3 * p], pin_positions_[3 * p + 1],
                                          pin_positions_[3 * p + 2], 1.0f);
    if (!(clip.w() > 1e-6f)) continue;
    const float x = clip.x() / clip.w(), y = clip.y() / clip.w();
    if (!(std::abs(x) < 2.0f && std::abs(y) < 2.0f)) continue;  // well off screen
    pin_screen_.push_back(0.5f * width * x);
    pin_screen_.push_back(0.5f * height * y);
    pins_in_front_.push_back(pin_vertices_[p]);
  }
  PinMarkRule rule;
  rule.largest *= pixel_ratio;
  rule.smallest *= pixel_ratio;
  const int shown = static_cast<int>(pins_in_front_.size());
  const std::vector<float>& diameters = sizes_.compute(pin_screen_.data(), shown, rule);
  for (int p = 0; p < shown; ++p)
    vertex_diameters_[pins_in_front_[p]] = diameters[p];
  return vertex_diameters_;
}

}  // namespace wobble

#include "app/interaction/view_framing.h"

#include <algorithm>

namespace wobble {

ViewportRegion region_beside_panel(float view_width, float panel_left, float panel_right) {
  ViewportRegion region;
  if (view_width <= 0.0f || panel_right <= panel_left) return region;
  const float left_free = std::clamp(panel_left, 0.0f, view_width);
  const float right_free = std::clamp(view_width - panel_right, 0.0f, view_width);
  if (std::max(left_free, right_free) < 0.25f * view_width) return region;
  if (right_free >= left_free) {
    region.left = 1.0f - right_free / view_width;
  } else {
    region.right = left_free / view_width;
  }
  return region;
}

ViewportRegion region_below(float view_height, float cover_bottom) {
  ViewportRegion region;
  if (view_height > 0.0f && cover_bottom > 0.0f && view_height - cover_bottom >= view_height / 3.0f)
    region.top = cover_bottom / view_height;
  return region;
}

ViewportRegion region_free_of(float view_width,
                              const std::vector<std::pair<float, float>>& covers) {
  ViewportRegion region;
  if (!(view_width > 0.0f)) return region;
  // Sweep the covered spans from the left; the widest gap between them wins.
  std::vector<std::pair<float, float>> spans;
  for (const auto& [left, right] : covers) {
    if (right > left)
      spans.emplace_back(std::clamp(left, 0.0f, view_width), std::clamp(right, 0.0f, view_width));
  }
  std::sort(spans.begin(), spans.end());
  float best_left = 0.0f, best_width = -1.0f, free_from = 0.0f;
  const auto consider = [&](float until) {
    if (until - free_from > best_width) {
      best_width = until - free_from;
      best_left = free_from;
    }
  };
  for (const auto& [left, right] : spans) {
    consider(left);
    free_from = std::max(free_from, right);
  }
  consider(view_width);
  if (spans.empty() || best_width < 0.25f * view_width) return region;
  region.left = best_left / view_width;
  region.right = (best_left + best_width) / view_width;
  return region;
}

void add_room_to_move(Eigen::Vector3f& lower, Eigen::Vector3f& upper, float ground_height) {
  const float room = 0.25f * (upper - lower).maxCoeff();
  lower -= Eigen::Vector3f(room, 0.0f, room);
  upper += Eigen::Vector3f(room, 0.0f, room);
  lower.y() = std::min(lower.y(), ground_height);
}

}  // namespace wobble

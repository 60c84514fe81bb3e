// The viewer's colouring by a quantity (spring strain, vertex speed) and its legend.
#include "ui/color_legend.h"
#include "viewer.h"

namespace wobble {

namespace {

// Samples of a colour map for the legend's bar: enough that the bar follows the map's curve.
constexpr int legend_samples = 33;

}  // namespace

void Viewer::update_quantity_colors() {
  // Coloured by material, this only clears what was there: no per-frame work.
  quantity_colors_.update(color_by(), *simulation_, /*with_springs=*/panel_.springs);
}

void Viewer::build_legend(float ui_scale) {
  const ColorQuantity quantity = quantity_colors_.quantity();
  if (quantity == ColorQuantity::material) return;
  const float range = quantity_colors_.range();
  ColorLegend legend;
  legend.colors.reserve(3 * legend_samples);
  for (int i = 0; i < legend_samples; ++i) {
    const float t = static_cast<float>(i) / (legend_samples - 1);
    const Eigen::Vector3f color =
        quantity == ColorQuantity::strain ? diverging_color(2.0f * t - 1.0f) : sequential_color(t);
    legend.colors.insert(legend.colors.end(), color.data(), color.data() + 3);
  }
  if (quantity == ColorQuantity::strain) {
    legend.title = "strain (length - rest) / rest";
    legend.low = "-" + two_significant_digits(100.0f * range) + "%";
    legend.middle = "0";
    legend.high = "+" + two_significant_digits(100.0f * range) + "%";
    legend.note = "compression blue, stretch red\nrange: 99th percentile, smoothed";
  } else {
    legend.title = "speed (m/s)";
    legend.low = "0";
    legend.high = two_significant_digits(range);
    legend.note = "range: 99th percentile, smoothed";
  }
  draw_color_legend(legend, ui_scale);
}

}  // namespace wobble

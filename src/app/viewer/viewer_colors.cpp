// The viewer's colouring by a quantity (spring strain, vertex speed, contacts, volume change) and
// its legend.
#include <algorithm>

#include "app/viewer/viewer.h"
#include "ui/color_legend.h"

namespace wobble {

namespace {

// Samples of a colour map for the legend's bar: enough that the bar follows the map's curve.
constexpr int legend_samples = 33;

// Three blocks, free, self contact and collider contact, each of as many samples as the bar's
// blend between neighbours stays a thin edge.
ColorLegend contacts_legend() {
  ColorLegend legend;
  legend.title = "contacts (last step)";
  legend.low = "free";
  legend.middle = "self";
  legend.high = "collider";
  legend.note = "magenta: self contact, blue: on a collider";
  for (const Eigen::Vector3f& color :
       {contact_free_color(), self_contact_color(), collider_contact_color()}) {
    for (int i = 0; i < legend_samples / 3; ++i)
      legend.colors.insert(legend.colors.end(), color.data(), color.data() + 3);
  }
  return legend;
}

}  // namespace

void Viewer::update_quantity_colors() {
  // Coloured by material, this only clears what was there: no per-frame work.
  const bool springs = panel_.springs;
  if (!right_.simulation()) {
    quantity_colors_.update(color_by(), host_.simulation(), springs);
    // A split view opened later starts its right side's range afresh.
    if (twin_colors_.quantity() != ColorQuantity::material) twin_colors_ = QuantityColors();
    return;
  }
  // Split, both sides share one range, so that a colour means the same on either.
  quantity_colors_.measure(color_by(), host_.simulation());
  twin_colors_.measure(color_by(), *right_.simulation());
  const float range = std::max(quantity_colors_.measured_range(), twin_colors_.measured_range());
  quantity_colors_.paint(host_.simulation(), range, springs);
  twin_colors_.paint(*right_.simulation(), range, springs);
}

void Viewer::add_quantity_colors(const QuantityColors& colors, MeshFrame& frame) const {
  // Colours from advance(), for this shape: a scene loaded since has none until its advance.
  const std::vector<float>& vertex_colors = colors.vertex_colors();
  const std::vector<float>& spring_colors = colors.spring_colors();
  if (vertex_colors.size() == positions_.size()) frame.vertex_colors = vertex_colors.data();
  if (!spring_colors.empty() && spring_colors.size() == 3 * springs_.size() / 2) {
    frame.spring_colors = spring_colors.data();
  }
}

void Viewer::build_legend(float ui_scale) {
  // A student's side is coloured by its distance from Wobble's, and that is what the legend says.
  if (right_.student()) {
    draw_student_legend(ui_scale);
    return;
  }
  const ColorQuantity quantity = quantity_colors_.quantity();
  if (quantity == ColorQuantity::material) return;
  LegendClearance clearance;
  clearance.instrument_column_left = instruments_left_;
  clearance.side_labels = right_.simulation() != nullptr;
  if (quantity == ColorQuantity::contacts) {
    draw_color_legend(contacts_legend(), ui_scale, clearance);
    return;
  }
  const float range = quantity_colors_.range();
  ColorLegend legend;
  legend.colors.reserve(3 * legend_samples);
  for (int i = 0; i < legend_samples; ++i) {
    const float t = static_cast<float>(i) / (legend_samples - 1);
    const Eigen::Vector3f color =
        quantity == ColorQuantity::speed ? sequential_color(t) : diverging_color(2.0f * t - 1.0f);
    legend.colors.insert(legend.colors.end(), color.data(), color.data() + 3);
  }
  if (quantity == ColorQuantity::strain) {
    legend.title = "strain (length - rest) / rest";
    legend.low = "-" + two_significant_digits(100.0f * range) + "%";
    legend.middle = "0";
    legend.high = "+" + two_significant_digits(100.0f * range) + "%";
    legend.note = "compression blue, stretch red\nrange: 99th percentile, smoothed";
  } else if (quantity == ColorQuantity::volume) {
    legend.title = "volume change (volume - rest) / rest";
    legend.low = "-" + two_significant_digits(100.0f * range) + "%";
    legend.middle = "0";
    legend.high = "+" + two_significant_digits(100.0f * range) + "%";
    legend.note = simulation().rest().T.rows() > 0
                      ? "each tetrahedron's, averaged at its corners\nsquashed blue, swollen red"
                      : "no tetrahedra: a solid's quantity";
  } else {
    legend.title = "speed (m/s)";
    legend.low = "0";
    legend.high = two_significant_digits(range);
    legend.note = "range: 99th percentile, smoothed";
  }
  draw_color_legend(legend, ui_scale, clearance);
}

}  // namespace wobble

// The viewer's draw state: the renderer's topology and colours for a scene, the plain arrays it
// draws from, the frame, whole or split into two sides beside the panel and the plots, and the
// colour legend.
#include "app/viewer/draw_state.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "app/interaction/view_framing.h"
#include "render/vertex_normals.h"
#include "ui/color_legend.h"

namespace wobble {

namespace {

// Cloth is orange in front and blue behind; a solid shows only its outside. A scene may choose.
SurfaceColors colors_for(const Scene& scene) {
  SurfaceColors colors;
  if (scene.name == "jelly") colors.front = Eigen::Vector3f(0.45f, 0.76f, 0.34f);
  if (scene.look.front_color) colors.front = scene.look.front_color->cast<float>();
  if (scene.look.back_color) colors.back = scene.look.back_color->cast<float>();
  return colors;
}

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

DrawState::~DrawState() = default;

void DrawState::set_shape(const Scene& scene, RgbaImage texture) {
  const SpringNetwork& network = scene.network;
  triangles_.resize(3 * network.F.rows());
  for (Eigen::Index f = 0; f < network.F.rows(); ++f) {
    for (int k = 0; k < 3; ++k)
      triangles_[3 * f + k] = static_cast<unsigned>(network.F(f, k));
  }
  springs_.resize(2 * network.E.rows());
  for (Eigen::Index e = 0; e < network.E.rows(); ++e) {
    for (int k = 0; k < 2; ++k)
      springs_[2 * e + k] = static_cast<unsigned>(network.E(e, k));
  }
  const int n = static_cast<int>(network.V.rows());
  positions_.resize(3 * n);
  normals_.resize(3 * n);
  marks_.resize(n);
  pinned_flags_.resize(n);
  const SceneLook& look = scene.look;
  uv_.clear();
  if (look.uv.rows() == n && look.uv.cols() == 2) {
    uv_.resize(2 * n);
    for (int i = 0; i < n; ++i) {
      uv_[2 * i] = static_cast<float>(look.uv(i, 0));
      uv_[2 * i + 1] = static_cast<float>(look.uv(i, 1));
    }
  }
  texture_ = std::move(texture);
  colors_ = colors_for(scene);
}

void DrawState::add_right_side() {
  twin_positions_.resize(positions_.size());
  twin_normals_.resize(normals_.size());
}

void DrawState::attach_renderer() {
  if (!renderer_) renderer_ = std::make_unique<Renderer>();
  MeshTopology topology;
  topology.vertex_count = static_cast<int>(positions_.size() / 3);
  topology.triangles = triangles_.data();
  topology.triangle_count = static_cast<int>(triangles_.size() / 3);
  topology.springs = springs_.data();
  topology.spring_count = static_cast<int>(springs_.size() / 2);
  topology.uv = uv_.empty() ? nullptr : uv_.data();
  renderer_->set_topology(topology);
  renderer_->set_colors(colors_);
  TextureImage texture;
  if (!texture_.pixels.empty()) {
    texture.rgba = texture_.pixels.data();
    texture.width = texture_.width;
    texture.height = texture_.height;
  }
  renderer_->set_texture(texture);

  renderer_->set_ground(ground_);
}

void DrawState::detach_renderer() {
  renderer_.reset();
}

void DrawState::update_vertex_arrays(const Simulation& left, const Simulation* right, int held,
                                     bool paused) {
  stale_ = false;
  const Eigen::MatrixXd& p = left.positions();
  const int n = static_cast<int>(p.rows());
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k)
      positions_[3 * i + k] = static_cast<float>(p(i, k));
    pinned_flags_[i] = left.is_pinned(i) ? 1 : 0;
  }
  // Paused, a drag moves only the pin's target: the held vertex is drawn there, its triangles
  // stretching towards it, so the user sees where the shape will be pulled (Step takes one step
  // towards it). The simulation's positions are untouched.
  if (paused && held >= 0) {
    const Eigen::Vector3d target = left.pin_target(held);
    for (int k = 0; k < 3; ++k)
      positions_[3 * held + k] = static_cast<float>(target(k));
  }
  compute_vertex_normals(positions_.data(), n, triangles_.data(),
                         static_cast<int>(triangles_.size() / 3), normals_.data());
  if (!right) return;
  const Eigen::MatrixXd& q = right->positions();
  twin_positions_.resize(3 * n);
  twin_normals_.resize(3 * n);
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k)
      twin_positions_[3 * i + k] = static_cast<float>(q(i, k));
  }
  compute_vertex_normals(twin_positions_.data(), n, triangles_.data(),
                         static_cast<int>(triangles_.size() / 3), twin_normals_.data());
}

void DrawState::update_quantity_colors(ColorQuantity quantity, const Simulation& left,
                                       const Simulation* right, bool springs) {
  // Coloured by material, this only clears what was there: no per-frame work.
  if (!right) {
    quantity_colors_.update(quantity, left, springs);
    // A split view opened later starts its right side's range afresh.
    if (twin_colors_.quantity() != ColorQuantity::material) twin_colors_ = QuantityColors();
    return;
  }
  // Split, both sides share one range, so that a colour means the same on either.
  quantity_colors_.measure(quantity, left);
  twin_colors_.measure(quantity, *right);
  const float range = std::max(quantity_colors_.measured_range(), twin_colors_.measured_range());
  quantity_colors_.paint(left, range, springs);
  twin_colors_.paint(*right, range, springs);
}

void DrawState::add_quantity_colors(const QuantityColors& colors, MeshFrame& frame) const {
  // Colours from the last refresh, for this shape: a scene loaded since has none until then.
  const std::vector<float>& vertex_colors = colors.vertex_colors();
  const std::vector<float>& spring_colors = colors.spring_colors();
  if (vertex_colors.size() == positions_.size()) frame.vertex_colors = vertex_colors.data();
  if (!spring_colors.empty() && spring_colors.size() == 3 * springs_.size() / 2) {
    frame.spring_colors = spring_colors.data();
  }
}

DrawState::SplitArea DrawState::split_area(float window, const PanelPlace& panel) const {
  float left = panel.shown ? panel.x + panel.width : 0.0f;
  float right = plots_left_ >= 0.0f ? std::min(window, plots_left_) : window;
  // Two halves narrower than a sixth of the window each show too little: then the whole
  // window, the panel and plots over it as before.
  if (right - left < window / 3.0f) {
    left = 0.0f;
    right = window;
  }
  return SplitArea{left, 0.5f * (right - left)};
}

PointerView DrawState::pointer_view(const Eigen::Vector2f& window, const PanelPlace& panel,
                                    bool split) const {
  // Split, each half is a view of its own under the same camera.
  PointerView picture;
  picture.view = view_;
  picture.projection = projection_;
  picture.positions = &positions_;
  picture.pinned = &pinned_flags_;
  picture.size = window;
  if (split) {
    const SplitArea area = split_area(window.x(), panel);
    picture.size = Eigen::Vector2f(area.half, window.y());
    picture.split = true;
    picture.left = area.left;
  }
  return picture;
}

void DrawState::render(
    const DrawInputs& in,
    const std::function<void(const PointerView&, std::vector<unsigned char>&)>& mark) {
  const PanelPlace& panel = in.panel;
  // Split, each side gets half of what the panel and the plots leave, under the same camera.
  const SplitArea area = split_area(in.window.x(), panel);
  const int left_x = in.split ? static_cast<int>(std::lround(area.left * in.pixel_ratio)) : 0;
  const int left_width =
      in.split ? static_cast<int>(std::lround(area.half * in.pixel_ratio)) : in.width;
  const float aspect = static_cast<float>(left_width) / std::max(in.height, 1);
  // Split, both sides share one camera and each is framed whole in its half; else the shape is
  // framed in what the panel and the plots leave free.
  std::vector<std::pair<float, float>> covers;
  if (!in.split) {
    if (panel.shown) covers.emplace_back(panel.x, panel.x + panel.width);
    if (plots_left_ >= 0.0f) covers.emplace_back(plots_left_, in.window.x());
  }
  ViewportRegion region = region_free_of(in.window.x(), covers);
  // A panel that leaves neither side room (a phone held upright): the shape below it, framed
  // again as the panel opens, folds or changes its height (it settles over a few frames).
  const bool below_panel = !in.split && panel.shown && region.left == 0.0f && region.right == 1.0f;
  if (below_panel) region = region_below(in.window.y(), panel.y + panel.height);
  // Only a framing below the panel follows its height (a tall panel leaves the whole view).
  const float panel_bottom = region.top > 0.0f ? panel.y + panel.height : 0.0f;
  const bool plots_open = plots_left_ >= 0.0f;
  // Framed again when the plots open or close, the panel is shown or hidden (Tab), or a panel as
  // wide as the view changes its height.
  if (plots_open != framed_with_plots_ || panel.shown != framed_with_panel_ ||
      std::abs(panel_bottom - framed_panel_bottom_) > 1.0f) {
    framed_with_plots_ = plots_open;
    framed_with_panel_ = panel.shown;
    framed_panel_bottom_ = panel_bottom;
    if (!camera_.framing_pending()) camera_.frame_next();
  }
  camera_.frame(positions_, ground_.height, region, aspect);
  const OrbitCamera& camera = camera_.camera();
  view_ = view_matrix(camera);
  projection_ = projection_matrix(camera, aspect);

  mark(pointer_view(in.window, panel, in.split), marks_);

  if (!renderer_ || !in.draw) return;
  SolidMesh solids;
  solids.positions = collider_mesh_.positions.data();
  solids.normals = collider_mesh_.normals.data();
  solids.vertex_count = collider_mesh_.vertex_count();
  solids.triangles = collider_mesh_.triangles.data();
  solids.triangle_count = collider_mesh_.triangle_count();
  renderer_->set_solids(solids);
  MeshFrame frame;
  frame.positions = positions_.data();
  frame.normals = normals_.data();
  frame.marks = marks_.data();
  add_quantity_colors(quantity_colors_, frame);
  renderer_->update(frame);
  if (in.split && area.left > 0.0f) {
    // The strips the two sides leave (under the panel and the plots) get the background alone.
    renderer_->draw(view_, projection_, camera_eye(camera),
                    ViewLayers{false, false, false, false, false, false}, in.width, in.height,
                    in.mark_scale);
  }
  renderer_->draw(view_, projection_, camera_eye(camera), in.layers, left_width, in.height,
                  in.mark_scale, left_x);
  if (!in.split) return;
  frame.positions = twin_positions_.data();
  frame.normals = twin_normals_.data();
  add_quantity_colors(twin_colors_, frame);
  if (in.right_colors && in.right_colors->size() == twin_positions_.size()) {
    frame.vertex_colors = in.right_colors->data();
  }
  renderer_->update(frame);
  renderer_->draw(view_, projection_, camera_eye(camera), in.layers,
                  std::min(left_width, in.width - left_x - left_width), in.height, in.mark_scale,
                  left_x + left_width);
}

void DrawState::draw_legend(float ui_scale, bool split, bool tetrahedra) const {
  const ColorQuantity quantity = quantity_colors_.quantity();
  if (quantity == ColorQuantity::material) return;
  LegendClearance clearance;
  clearance.instrument_column_left = plots_left_;
  clearance.side_labels = split;
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
    legend.note = tetrahedra
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

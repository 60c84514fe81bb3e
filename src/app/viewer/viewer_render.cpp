// The viewer's drawing: the renderer's topology and colours for a scene, the plain arrays it
// draws from, and the frame, whole or split into two sides beside the panel and the plots.
#include <algorithm>
#include <cmath>

#include "app/interaction/view_framing.h"
#include "app/viewer/viewer.h"
#include "render/vertex_normals.h"

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

}  // namespace

void Viewer::attach_renderer() {
  if (!renderer_) renderer_ = std::make_unique<Renderer>();
  MeshTopology topology;
  topology.vertex_count = static_cast<int>(scene_.network.V.rows());
  topology.triangles = triangles_.data();
  topology.triangle_count = static_cast<int>(triangles_.size() / 3);
  topology.springs = springs_.data();
  topology.spring_count = static_cast<int>(springs_.size() / 2);
  topology.uv = uv_.empty() ? nullptr : uv_.data();
  renderer_->set_topology(topology);
  renderer_->set_colors(colors_for(scene_));
  TextureImage texture;
  if (!texture_.pixels.empty()) {
    texture.rgba = texture_.pixels.data();
    texture.width = texture_.width;
    texture.height = texture_.height;
  }
  renderer_->set_texture(texture);

  renderer_->set_ground(ground_);
}

void Viewer::update_vertex_arrays() {
  arrays_stale_ = false;
  const Eigen::MatrixXd& p = host_.simulation().positions();
  const int n = static_cast<int>(p.rows());
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k)
      positions_[3 * i + k] = static_cast<float>(p(i, k));
    pinned_flags_[i] = host_.simulation().is_pinned(i) ? 1 : 0;
  }
  // Paused, a drag moves only the pin's target: the held vertex is drawn there, its triangles
  // stretching towards it, so the user sees where the shape will be pulled (Step takes one step
  // towards it). The simulation's positions are untouched.
  const int held = pick_and_drag_.held_vertex();
  if (panel_.paused && held >= 0) {
    const Eigen::Vector3d target = host_.simulation().pin_target(held);
    for (int k = 0; k < 3; ++k)
      positions_[3 * held + k] = static_cast<float>(target(k));
  }
  compute_vertex_normals(positions_.data(), n, triangles_.data(),
                         static_cast<int>(triangles_.size() / 3), normals_.data());
  if (!right_.simulation()) return;
  const Eigen::MatrixXd& q = right_.simulation()->positions();
  twin_positions_.resize(3 * n);
  twin_normals_.resize(3 * n);
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k)
      twin_positions_[3 * i + k] = static_cast<float>(q(i, k));
  }
  compute_vertex_normals(twin_positions_.data(), n, triangles_.data(),
                         static_cast<int>(triangles_.size() / 3), twin_normals_.data());
}

void Viewer::render(int framebuffer_width, int framebuffer_height,
                    const Eigen::Vector2f& window_size, float pixel_ratio,
                    std::optional<float> mark_scale_given, bool draw) {
  const float mark_scale = mark_scale_given.value_or(pixel_ratio);
  // Split, each side gets half of what the panel and the plots leave, under the same camera.
  const SplitArea area = split_area(window_size.x());
  const int left_x =
      right_.simulation() ? static_cast<int>(std::lround(area.left * pixel_ratio)) : 0;
  const int left_width = right_.simulation()
                             ? static_cast<int>(std::lround(area.half * pixel_ratio))
                             : framebuffer_width;
  // Between batches a change made since the last refresh is read afresh (a paused drag moves
  // the drawn pin); while a batch runs, the state it started from is drawn.
  if (!host_.batch_started() && arrays_stale_) update_vertex_arrays();
  const float aspect = static_cast<float>(left_width) / std::max(framebuffer_height, 1);
  // Split, both sides share one camera and each is framed whole in its half; else the shape is
  // framed in what the panel and the plots leave free.
  std::vector<std::pair<float, float>> covers;
  if (!right_.simulation()) {
    if (panel_place_.shown) {
      covers.emplace_back(panel_place_.x, panel_place_.x + panel_place_.width);
    }
    if (instruments_left_ >= 0.0f) covers.emplace_back(instruments_left_, window_size.x());
  }
  ViewportRegion region = region_free_of(window_size.x(), covers);
  // A panel that leaves neither side room (a phone held upright): the shape below it, framed
  // again as the panel opens, folds or changes its height (it settles over a few frames).
  const bool below_panel =
      !right_.simulation() && panel_place_.shown && region.left == 0.0f && region.right == 1.0f;
  if (below_panel) region = region_below(window_size.y(), panel_place_.y + panel_place_.height);
  // Only a framing below the panel follows its height (a tall panel leaves the whole view).
  const float panel_bottom = region.top > 0.0f ? panel_place_.y + panel_place_.height : 0.0f;
  const bool plots_open = instruments_left_ >= 0.0f;
  // Framed again when the plots open or close, the panel is shown or hidden (Tab), or a panel as
  // wide as the view changes its height.
  if (plots_open != framed_with_plots_ || panel_place_.shown != framed_with_panel_ ||
      std::abs(panel_bottom - framed_panel_bottom_) > 1.0f) {
    framed_with_plots_ = plots_open;
    framed_with_panel_ = panel_place_.shown;
    framed_panel_bottom_ = panel_bottom;
    if (!view_camera_.framing_pending()) view_camera_.frame_next();
  }
  view_camera_.frame(positions_, ground_.height, region, aspect);
  const OrbitCamera& camera = view_camera_.camera();
  view_ = view_matrix(camera);
  projection_ = projection_matrix(camera, aspect);

  pick_and_drag_.mark(pointer_view(window_size), marks_);

  update_collider_mesh();
  if (!renderer_ || !draw) return;
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
  if (right_.simulation() && area.left > 0.0f) {
    // The strips the two sides leave (under the panel and the plots) get the background alone.
    renderer_->draw(view_, projection_, camera_eye(camera),
                    ViewLayers{false, false, false, false, false, false}, framebuffer_width,
                    framebuffer_height, mark_scale);
  }
  renderer_->draw(view_, projection_, camera_eye(camera), layers(), left_width, framebuffer_height,
                  mark_scale, left_x);
  if (!right_.simulation()) return;
  frame.positions = twin_positions_.data();
  frame.normals = twin_normals_.data();
  add_quantity_colors(twin_colors_, frame);
  if (right_.student() && shown_student_colors_.size() == twin_positions_.size()) {
    frame.vertex_colors = shown_student_colors_.data();
  }
  renderer_->update(frame);
  renderer_->draw(view_, projection_, camera_eye(camera), layers(),
                  std::min(left_width, framebuffer_width - left_x - left_width), framebuffer_height,
                  mark_scale, left_x + left_width);
}

ViewLayers Viewer::layers() const {
  ViewLayers layers;
  layers.surface = panel_.surface;
  layers.wireframe = panel_.wireframe;
  layers.springs = panel_.springs;
  layers.points = panel_.points;
  layers.ground = panel_.ground;
  layers.solids = panel_.colliders;
  return layers;
}

}  // namespace wobble

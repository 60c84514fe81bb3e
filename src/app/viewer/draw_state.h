#ifndef WOBBLE_APP_VIEWER_DRAW_STATE_H
#define WOBBLE_APP_VIEWER_DRAW_STATE_H

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <vector>

#include "app/interaction/collider_mesh.h"
#include "app/viewer/pick_and_drag.h"
#include "app/viewer/quantity_colors.h"
#include "app/viewer/view_camera.h"
#include "io/png_image.h"
#include "render/renderer.h"
#include "sim/shapes/builtin_scenes.h"
#include "sim/simulation.h"
#include "ui/control_panel.h"

namespace wobble {

// What one render draws with, handed in by the viewer.
struct DrawInputs {
  int width = 0, height = 0;                         // the framebuffer's pixels
  Eigen::Vector2f window = Eigen::Vector2f::Zero();  // in the units of the mouse events
  float pixel_ratio = 1.0f;                          // framebuffer pixels per window unit
  float mark_scale = 1.0f;  // framebuffer pixels per pixel of a mark's size
  bool draw = true;         // false: only what drawing would change besides the pixels
  PanelPlace panel;         // where the panel lies (not shown: hidden or folded)
  bool split = false;       // the split view's right side drawn beside the left
  ViewLayers layers;
  // The right side's vertex colours (a student's step, by its distance), or null.
  const std::vector<float>* right_colors = nullptr;
};

// The viewer's draw state, a component of it: the camera (ViewCamera), the plain arrays the
// renderer draws from (positions, normals, marks, colours by a quantity, of both sides of a split
// view), the scene's topology, texture and colours, the ground grid and the colliders' triangles,
// the last frame's matrices and framing, and the renderer. It reads the simulations it is given
// and draws; it changes nothing of them.
class DrawState {
 public:
  DrawState(std::optional<float> yaw, std::optional<float> pitch, float zoom)
      : camera_(yaw, pitch, zoom) {}
  ~DrawState();

  const OrbitCamera& camera() const { return camera_.camera(); }
  // The camera as the command line's angles and zoom give it back (the page's Copy link).
  ViewCamera::Angles camera_angles() const { return camera_.angles(); }
  // How far the mouse may take the camera, for this scene's shape and ground.
  const CameraLimits& camera_limits() const { return camera_.limits(); }
  // #V by 3 positions as the last render drew them (a paused drag draws the held vertex at its
  // target).
  const std::vector<float>& drawn_positions() const { return positions_; }
  // The colours the last refresh computed (empty while coloured by material).
  const QuantityColors& quantity_colors() const { return quantity_colors_; }
  // The ground grid under the scene (see ground_grid_height), set when a scene loads.
  const GroundGrid& ground() const { return ground_; }
  // The colliders' triangles as the last render drew them (empty while they are hidden).
  const ColliderTriangles& collider_mesh() const { return collider_mesh_; }
  // Create the renderer (the GL context current until detach_renderer or destruction), or give
  // the one there the scene's topology, colours, texture and ground again.
  void attach_renderer();
  // Free the renderer's GL objects while their context is still current.
  void detach_renderer();
  bool has_renderer() const { return renderer_ != nullptr; }

  // What the viewer's wiring uses.
  ViewCamera& view_camera() { return camera_; }
  GroundGrid& ground_grid() { return ground_; }
  ColliderTriangles& colliders() { return collider_mesh_; }
  // A new scene's topology, texture coordinates, colours and `texture`; the arrays sized for it.
  void set_shape(const Scene& scene, RgbaImage texture);
  // The split view's right side is drawn from now on: its arrays sized as the left's.
  void add_right_side();
  // The arrays are stale after a change the last refresh did not see.
  void mark_stale() { stale_ = true; }
  bool stale() const { return stale_; }
  // The arrays from the simulations' positions: `held` (>= 0), paused, is drawn at its pin
  // target.
  void update_vertex_arrays(const Simulation& left, const Simulation* right, int held, bool paused);
  // The colours by `quantity`, both sides of a split view in one range.
  void update_quantity_colors(ColorQuantity quantity, const Simulation& left,
                              const Simulation* right, bool springs);
  // The plot column's left edge (window units), < 0 while closed.
  void set_plots_left(float left) { plots_left_ = left; }
  float plots_left() const { return plots_left_; }
  // Split, the part of a window `window` wide that the two sides share (window units): what the
  // panel and the plots leave, in two halves of `half` from `left`; the whole window when that
  // part is too narrow to see anything in.
  struct SplitArea {
    float left = 0.0f, half = 0.0f;
  };
  SplitArea split_area(float window, const PanelPlace& panel) const;
  // The picture as the last render drew it, for the mouse in a window `window` big.
  PointerView pointer_view(const Eigen::Vector2f& window, const PanelPlace& panel,
                           bool split) const;
  // Frame the camera in what the panel and the plots leave (or each half, split), `mark` the
  // marks on the picture so framed, and draw into the bound framebuffer unless `!inputs.draw`.
  void render(const DrawInputs& inputs,
              const std::function<void(const PointerView&, std::vector<unsigned char>&)>& mark);
  // The colour bar of the quantity the last refresh coloured by (ImGui, before ImGui::Render);
  // nothing for material. `tetrahedra`: the scene has a volume.
  void draw_legend(float ui_scale, bool split, bool tetrahedra) const;

 private:
  void add_quantity_colors(const QuantityColors& colors, MeshFrame& frame) const;

  ViewCamera camera_;  // the camera, its opening view and framing
  float plots_left_ = -1.0f;
  bool framed_with_plots_ = false;    // the plots were open when the view was last framed
  bool framed_with_panel_ = false;    // ... and the panel shown
  float framed_panel_bottom_ = 0.0f;  // ... and the bottom of a panel as wide as it (0: none)
  bool stale_ = false;
  std::vector<unsigned> triangles_, springs_;
  std::vector<float> positions_, normals_;
  std::vector<unsigned char> marks_, pinned_flags_;
  std::vector<float> twin_positions_, twin_normals_;  // the split view's right side
  std::vector<float> uv_;                             // #V by 2, or empty
  RgbaImage texture_;
  SurfaceColors colors_;
  GroundGrid ground_;
  ColliderTriangles collider_mesh_;
  QuantityColors quantity_colors_;  // empty while coloured by material
  QuantityColors twin_colors_;      // the split view's right side, in the same range
  Eigen::Matrix4f view_ = Eigen::Matrix4f::Identity();
  Eigen::Matrix4f projection_ = Eigen::Matrix4f::Identity();
  std::unique_ptr<Renderer> renderer_;
};

}  // namespace wobble

#endif

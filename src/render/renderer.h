#ifndef WOBBLE_RENDER_RENDERER_H
#define WOBBLE_RENDER_RENDERER_H

#include <Eigen/Core>
#include <memory>

namespace wobble {

// What connects the vertices; changes only when a scene is loaded. Plain arrays, row-major.
struct MeshTopology {
  int vertex_count = 0;
  const unsigned* triangles = nullptr;  // #F by 3 vertex indices, counter-clockwise from the front
  int triangle_count = 0;
  const unsigned* springs = nullptr;  // #E by 2 vertex indices
  int spring_count = 0;
  const float* uv = nullptr;  // #V by 2 texture coordinates (v up, as in OBJ), or null
};

// An 8-bit RGBA image for the surface, rows from the top (as image files store them).
struct TextureImage {
  const unsigned char* rgba = nullptr;
  int width = 0, height = 0;
};

// Where the vertices are this frame. Plain arrays of topology.vertex_count rows.
struct MeshFrame {
  const float* positions = nullptr;      // #V by 3 (m)
  const float* normals = nullptr;        // #V by 3 unit normals
  const unsigned char* marks = nullptr;  // #V: 0 free, 1 pinned, 2 highlighted
  // Colours by a quantity (strain, speed), linear RGB in [0, 1]; null for the material colours.
  // Set, they replace the surface's colours and texture (still lit) and the springs' one colour.
  const float* vertex_colors = nullptr;  // #V by 3, interpolated across the triangles
  const float* spring_colors = nullptr;  // #E by 3, one colour per spring line
};

// Which layers to draw.
struct ViewLayers {
  bool surface = true;     // shaded triangles, two-sided
  bool wireframe = false;  // triangle edges
  // Every spring as a line, interior ones included; for a topology without triangles (a rope, a
  // net) the springs are the body, drawn as bands several pixels wide in the front colour.
  bool springs = false;
  bool points = false;  // every vertex as a dot (pins are always marked, smaller when dense)
  bool ground = true;   // grid on the ground plane
  bool solids = true;   // the solid meshes of set_solids (colliders)
};

// The square grid on the ground plane y = height, centred under (center_x, center_z).
struct GroundGrid {
  float height = 0.0f;
  float center_x = 0.0f, center_z = 0.0f;
  float half_extent = 2.0f;  // m
  float spacing = 0.25f;     // m between lines
};

// Shaded solids drawn with the surface's two-sided lighting in one colour (the colliders). Plain
// arrays; they may change every frame.
struct SolidMesh {
  const float* positions = nullptr;  // #V by 3 (m)
  const float* normals = nullptr;    // #V by 3 outward unit normals
  int vertex_count = 0;
  const unsigned* triangles = nullptr;  // #F by 3 indices, counter-clockwise from outside
  int triangle_count = 0;
};

// Colours of the surface, linear RGB in [0, 1].
struct SurfaceColors {
  Eigen::Vector3f front{0.95f, 0.55f, 0.22f};
  Eigen::Vector3f back{0.26f, 0.55f, 0.85f};
  Eigen::Vector3f solid{0.62f, 0.64f, 0.67f};  // colliders: a neutral grey, inside and out
};

// Draws one frame into whatever framebuffer is bound: a window's or an offscreen one. It never
// knows which, and takes plain arrays, not simulation types. Needs a current GL 3.3 core context
// with glad loaded, for its whole life.
class Renderer {
 public:
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  void set_topology(const MeshTopology& topology);
  void set_ground(const GroundGrid& ground);
  void set_colors(const SurfaceColors& colors);
  // Paint the surface with `image` through the topology's uv; an empty image goes back to the
  // plain colours. Without uv the texture is not used.
  void set_texture(const TextureImage& image);
  // Replace the solids (an empty mesh draws none).
  void set_solids(const SolidMesh& solids);
  // Upload this frame's vertices (topology.vertex_count of each array).
  void update(const MeshFrame& frame);
  // Clear and draw the scene in a viewport of width × height pixels whose lower left corner is
  // (x, y) (a split view draws twice, side by side; only the viewport is cleared). `pixel_ratio`
  // scales point sizes on high-DPI framebuffers.
  void draw(const Eigen::Matrix4f& view, const Eigen::Matrix4f& projection,
            const Eigen::Vector3f& eye, const ViewLayers& layers, int width, int height,
            float pixel_ratio = 1.0f, int x = 0, int y = 0);

 private:
  // Each pin marker's diameter from the pins' spacing on screen under this view.
  void size_pin_marks(const Eigen::Matrix4f& view_projection, int width, int height,
                      float pixel_ratio);

  struct Resources;
  std::unique_ptr<Resources> resources_;
};

}  // namespace wobble

#endif

#include "builtin_scenes.h"

#include "cloth_grid.h"
#include "jelly_block.h"
#include "sim/input_error.h"

namespace wobble {

namespace {

// The shipped jellies' volume stiffness (Pa), as assets/jelly_drop.json and blob_jelly.json set.
constexpr double jelly_volume_stiffness = 2e4;

Scene make_cloth_scene() {
  Scene scene;
  scene.name = "cloth";
  scene.description = "40x40 cloth hanging from its two top corners";
  ClothGridOptions options;
  scene.network = make_cloth_grid(options);
  scene.network.V.col(1).array() += 1.2;
  const int n = options.resolution;
  scene.pins = {cloth_grid_vertex(n, 0, 0), cloth_grid_vertex(n, 0, n - 1)};
  scene.params.k = 400.0;
  scene.params.dt = 1.0 / 60.0;
  scene.params.iterations = 50;
  return scene;
}

Scene make_jelly_scene() {
  Scene scene;
  scene.name = "jelly";
  scene.description = "tetrahedral jelly block with its base pinned, swaying";
  JellyBlockOptions options;
  scene.network = make_jelly_block(options);
  const Eigen::MatrixXd& V = scene.network.V;
  for (Eigen::Index i = 0; i < V.rows(); ++i) {
    if (V(i, 1) == 0.0) scene.pins.push_back(static_cast<int>(i));
  }
  // A shear: sideways velocity proportional to height, so the block sways from the first frame.
  scene.initial_velocity = Eigen::MatrixXd::Zero(V.rows(), 3);
  scene.initial_velocity.col(0) = 2.0 * V.col(1) / options.size;
  scene.params.k = 1500.0;
  scene.params.dt = 1.0 / 60.0;
  scene.params.iterations = 50;
  // The volume term beside the springs: a jelly turned inside out comes back (volume_term.h).
  scene.params.added_settings["volume"] = 1.0;
  scene.params.added_settings["volume-stiffness"] = jelly_volume_stiffness;
  return scene;
}

}  // namespace

std::vector<std::string> builtin_scene_names() {
  return {"cloth", "jelly"};
}

Scene make_builtin_scene(const std::string& name) {
  if (name == "cloth") return make_cloth_scene();
  if (name == "jelly") return make_jelly_scene();
  std::string known;
  for (const std::string& candidate : builtin_scene_names()) {
    known += (known.empty() ? "" : ", ") + candidate;
  }
  throw InputError("unknown scene '" + name + "' (built-in scenes: " + known + ")");
}

}  // namespace wobble

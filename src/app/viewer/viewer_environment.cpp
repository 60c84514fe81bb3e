// The viewer's environment: the panel's controls of the settings both sides share (damping,
// friction, wind, self-collision: app/viewer/side_settings.h), the ground grid under the scene,
// and the colliders' triangles.
#include <algorithm>
#include <cmath>

#include "app/interaction/ground_placement.h"
#include "app/viewer/side_settings.h"
#include "app/viewer/viewer.h"

namespace wobble {

void Viewer::show_environment_in_panel() {
  show_settings(host_.simulation().params(), panel_.environment, scene_.network.T.rows() > 0,
                PanelPart::environment);
}

void Viewer::place_ground() {
  const SpringNetwork& network = scene_.network;
  Eigen::Vector3f lower = Eigen::Vector3f::Zero(), upper = Eigen::Vector3f::Zero();
  if (network.V.rows() > 0) {
    lower = network.V.colwise().minCoeff().cast<float>();
    upper = network.V.colwise().maxCoeff().cast<float>();
  }
  // Lines at a round fraction of the scene's size.
  const float size = std::max((upper - lower).maxCoeff(), 1e-3f);
  ground_.height = static_cast<float>(
      ground_grid_height(network.V, network.E, scene_.pins, host_.simulation().colliders()));
  ground_.center_x = 0.5f * (lower.x() + upper.x());
  ground_.center_z = 0.5f * (lower.z() + upper.z());
  ground_.spacing = 0.25f * std::pow(10.0f, std::round(std::log10(size)));
  ground_.half_extent =
      8.0f * ground_.spacing * std::max(1.0f, std::ceil(size / (4 * ground_.spacing)));
}

void Viewer::update_collider_mesh() {
  collider_mesh_ = ColliderTriangles();
  if (!panel_.colliders) return;
  // A plane is drawn as a square as large as the grid, centred nearest the scene.
  const Eigen::Vector3f focus(ground_.center_x, ground_.height, ground_.center_z);
  collider_mesh_ = collider_triangles(host_.simulation().colliders(), focus, ground_.half_extent);
}

}  // namespace wobble

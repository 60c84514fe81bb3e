// The viewer's environment: damping, friction, wind and self-collision as the panel and the W key
// set them, the ground grid under the scene, and the colliders' triangles.
#include <algorithm>
#include <cmath>

#include "app/interaction/environment_controls.h"
#include "app/interaction/ground_placement.h"
#include "app/viewer/viewer.h"
#include "sim/contact/collider_contact_term.h"
#include "sim/value_limits.h"

namespace wobble {

void Viewer::show_environment_in_panel() {
  const SimulationParams& params = host_.simulation().params();
  panel_.damping = static_cast<float>(params.damping);
  panel_.friction = static_cast<float>(params.contact.friction);
  panel_.wind = params.wind.on;
  panel_.wind_speed = shown_wind_speed_ = static_cast<float>(wind_speed(params.wind));
  panel_.wind_heading = shown_wind_heading_ = static_cast<float>(wind_heading_degrees(params.wind));
  panel_.self_collision = params.self_collision.on;
  panel_.self_collision_mm = static_cast<float>(1000.0 * params.self_collision.thickness);
}

bool Viewer::environment_settings(SimulationParams& wanted) {
  const SimulationParams params = wanted;
  // Damping re-factorizes Q; friction and wind cost nothing (Simulation::apply).
  if (static_cast<float>(params.damping) != panel_.damping) wanted.damping = panel_.damping;
  if (static_cast<float>(params.contact.friction) != panel_.friction) {
    wanted.contact.friction = panel_.friction;
  }
  bool wind_toggled = false;
  if (params.wind.on != panel_.wind) {
    // The checkbox does what the W key does, breeze included.
    wanted.wind = toggled_wind(params.wind);
    wind_toggled = true;
  } else if (panel_.wind_speed != shown_wind_speed_ || panel_.wind_heading != shown_wind_heading_) {
    wanted.wind = wind_with_speed_and_heading(params.wind, panel_.wind_speed, panel_.wind_heading);
    shown_wind_speed_ = panel_.wind_speed;
    shown_wind_heading_ = panel_.wind_heading;
  }
  // Nothing precomputed either. The checkbox alone keeps the thickness as it is (a float's mm
  // would not give 0.01 m back exactly); the slider's value is clamped, as a float's rounding can
  // fall just outside the limits. A course scene is offered neither.
  const SelfCollisionParams& self = params.self_collision;
  const bool course = params.gravity_model == GravityModel::force_per_vertex;
  const bool thickness_moved =
      static_cast<float>(1000.0 * self.thickness) != panel_.self_collision_mm;
  if (!course && (self.on != panel_.self_collision || thickness_moved)) {
    SelfCollisionParams changed = self;
    changed.on = panel_.self_collision;
    if (thickness_moved) {
      const ValueRange& range = limits::self_collision_thickness;
      changed.thickness = std::clamp(1e-3 * panel_.self_collision_mm, range.low, range.high);
    }
    wanted.self_collision = changed;
    panel_.self_collision_mm = static_cast<float>(1000.0 * changed.thickness);
  }
  return wind_toggled;
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
  ground_.height = static_cast<float>(ground_grid_height(network.V, network.E, scene_.pins,
                                                         colliders_in(host_.simulation().terms())));
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
  collider_mesh_ =
      collider_triangles(colliders_in(host_.simulation().terms()), focus, ground_.half_extent);
}

}  // namespace wobble

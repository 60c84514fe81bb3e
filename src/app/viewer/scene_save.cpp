#include "app/viewer/scene_save.h"

#include <filesystem>

#include "io/write_wobble_scene.h"
#include "sim/contact/collider_contact_term.h"

namespace wobble {

Scene scene_to_save(
    const Scene& opened, const Simulation& simulation,
    const std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>>& camera_position_target) {
  Scene scene;
  scene.name = opened.name;
  scene.description = opened.description;
  // The rest shape, not opened.network: the simulation owns what it steps, and the two only
  // differ if the caller opened one scene and simulates another.
  scene.network = simulation.rest();
  scene.pins = simulation.pinned_vertices();
  scene.params = simulation.params();
  // The colliders as they are now; params() keeps the ones the scene placed.
  scene.params.contact.colliders = colliders_in(simulation.terms());
  scene.initial_velocity = opened.initial_velocity;
  scene.look = opened.look;
  if (camera_position_target) {
    scene.look.camera_position = camera_position_target->first;
    scene.look.camera_target = camera_position_target->second;
  }
  return scene;
}

void save_current_scene(
    const std::string& json_path, const Scene& opened, const Simulation& simulation,
    const std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>>& camera_position_target) {
  Scene scene = scene_to_save(opened, simulation, camera_position_target);
  // A saved scene is a scene of its own: the picker and the outputs name it as its file.
  scene.name = std::filesystem::path(json_path).stem().string();
  write_wobble_scene(json_path, scene);
}

}  // namespace wobble

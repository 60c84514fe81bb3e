#ifndef WOBBLE_APP_VIEWER_SCENE_SAVE_H
#define WOBBLE_APP_VIEWER_SCENE_SAVE_H

#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>

#include "sim/scene.h"
#include "sim/simulation.h"

namespace wobble {

// The scene the viewer shows, as it would be saved: the rest network, name, description, initial
// velocity and look of `opened` (the scene as it was loaded), with the simulation's current
// settings (simulation.params(): k, dt, iterations, Chebyshev, gravity and its model, damping,
// wind, friction, contact offset), its current pins (simulation.pinned_vertices()) and its
// colliders where they are now (colliders_in(simulation.terms()), which may have been dragged).
// `camera_position_target`, when given, replaces the camera (position, target in m).
//
// The format stores pins as vertex indices only, so a pin dragged to a new target is saved as a
// pin at its rest position; the deformed state (positions, velocities, time) is not saved either:
// the saved scene starts where `opened` started, with today's settings.
Scene scene_to_save(
    const Scene& opened, const Simulation& simulation,
    const std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>>& camera_position_target);

// Write scene_to_save(...) as a Wobble scene file at `json_path` with its mesh beside it (see
// io/write_wobble_scene.h, which says what it throws), so that `wobble json_path` starts the
// same simulation.
void save_current_scene(
    const std::string& json_path, const Scene& opened, const Simulation& simulation,
    const std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>>& camera_position_target);

}  // namespace wobble

#endif

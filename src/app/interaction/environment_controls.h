#ifndef WOBBLE_APP_INTERACTION_ENVIRONMENT_CONTROLS_H
#define WOBBLE_APP_INTERACTION_ENVIRONMENT_CONTROLS_H

#include <Eigen/Core>

#include "sim/forces/wind.h"

namespace wobble {

// What the W key and the panel's wind checkbox do: `on` flipped. Turning on an aerodynamic wind
// whose velocity is zero gives WindParams::default_breeze() instead, so the key always shows
// something; the course's wind keeps its own model and only flips.
WindParams toggled_wind(const WindParams& wind);

// The panel's view of an aerodynamic wind: its speed |velocity| (m/s) and its heading, the
// direction it blows towards around the y axis in degrees in [0, 360): 0 towards +x, 90
// towards +z.
double wind_speed(const WindParams& wind);
double wind_heading_degrees(const WindParams& wind);
// The wind with that speed (m/s) and heading (degrees), keeping the velocity's elevation above
// the horizontal (none when it was zero) and everything else.
WindParams wind_with_speed_and_heading(const WindParams& wind, double speed,
                                       double heading_degrees);

// Gravity of the given magnitude (m/s², or N for the course's model) along the scene's own
// direction: the gravity slider changes only the strength. A scene without gravity gets it
// straight down.
Eigen::Vector3d gravity_with_magnitude(const Eigen::Vector3d& scene_gravity, double magnitude);

}  // namespace wobble

#endif

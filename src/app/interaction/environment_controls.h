#ifndef WOBBLE_APP_INTERACTION_ENVIRONMENT_CONTROLS_H
#define WOBBLE_APP_INTERACTION_ENVIRONMENT_CONTROLS_H

#include <Eigen/Core>

namespace wobble {

// The panel's view of a vector as a speed |v| and a heading, the direction it points towards
// around the y axis in degrees in [0, 360): 0 towards +x, 90 towards +z (the wind's velocity).
double heading_degrees(const Eigen::Vector3d& v);
// `v` with that speed and heading (degrees), keeping its elevation above the horizontal (none
// when it was zero).
Eigen::Vector3d with_speed_and_heading(const Eigen::Vector3d& v, double speed,
                                       double heading_degrees);

}  // namespace wobble

#endif

#ifndef WOBBLE_SIM_SCENE_H
#define WOBBLE_SIM_SCENE_H

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "sim/settings/simulation_params.h"
#include "sim/spring_network.h"

namespace wobble {

// How a scene asks to be shown. None of it affects the simulation.
struct SceneLook {
  std::optional<Eigen::Vector3d> camera_position;  // m; with camera_target, replaces framing
  std::optional<Eigen::Vector3d> camera_target;    // m
  std::optional<Eigen::Vector3d> front_color;      // linear RGB in [0, 1]
  std::optional<Eigen::Vector3d> back_color;
  Eigen::MatrixXd uv;   // #V by 2 texture coordinates in [0, 1] (v up, as OBJ), or empty
  std::string texture;  // PNG file, absolute or relative to the working folder; empty: none
};

// Everything needed to start a Simulation and show it: the rest shape, the initial pins (vertex
// indices), default parameters, the initial velocity (#V by 3, or empty for rest), and the look.
struct Scene {
  std::string name;
  std::string description;
  SpringNetwork network;
  std::vector<int> pins;
  SimulationParams params;
  Eigen::MatrixXd initial_velocity;
  SceneLook look;
  // What the loader chose on the user's behalf (e.g. "no pins given: pinned the 3 top-most
  // vertices"), said on stderr and shown in the panel.
  std::vector<std::string> notes;
};

}  // namespace wobble

#endif

#include "self_collision_cost.h"

#include <cmath>
#include <cstdio>
#include <vector>

#include "median.h"
#include "sim/shapes/cloth_grid.h"
#include "sim/simulation.h"

namespace wobble::benchmark {

namespace {

constexpr double pi = 3.14159265358979323846;

struct PhaseTimes {
  std::vector<double> total, detection, response;
  void add(const StepTiming& timing) {
    total.push_back(timing.total_ms);
    detection.push_back(timing.self_detection_ms);
    response.push_back(timing.self_response_ms);
  }
};

// The cloth_pile asset's cloth: upright, 1 m square, pleated along x, lower edge 5 cm up, no bend
// springs, thrown down at 2.5 m/s.
void print_pile() {
  ClothGridOptions options;
  options.resolution = 40;
  options.bend = false;
  SpringNetwork cloth = make_cloth_grid(options);
  for (Eigen::Index i = 0; i < cloth.V.rows(); ++i) {
    const double x = cloth.V(i, 0), z = cloth.V(i, 2);
    cloth.V(i, 1) = 0.55 - z;
    cloth.V(i, 2) = 0.05 * std::sin(2.0 * pi * x / 0.25);
  }
  Eigen::MatrixXd velocity = Eigen::MatrixXd::Zero(cloth.V.rows(), 3);
  velocity.col(1).setConstant(-2.5);
  SimulationParams params;
  params.damping = 0.2;
  params.contact.friction = 0.4;
  params.contact.colliders = {Collider{}};
  PhaseTimes folding[2], resting[2];
  int contacts = 0;
  for (const bool on : {false, true}) {
    params.self_collision.on = on;
    Simulation simulation(cloth, {}, params, velocity);
    for (int step = 0; step < 400; ++step) {
      simulation.step();
      if (step < 150) folding[on].add(simulation.last_step_timing());
      if (step >= 300) resting[on].add(simulation.last_step_timing());
    }
    if (on) contacts = simulation.self_contact_count();
  }
  for (int phase = 0; phase < 2; ++phase) {
    const PhaseTimes* times = phase == 0 ? folding : resting;
    const double off = median(times[0].total), on = median(times[1].total);
    std::printf(
        "self-collision/40x40 pile %-8s  off %.2f ms  on %.2f ms (%.2fx)  detection %.2f ms  "
        "response %.2f ms%s\n",
        phase == 0 ? "folding" : "at rest", off, on, on / off, median(times[1].detection),
        median(times[1].response),
        phase == 1 ? ("  " + std::to_string(contacts) + " vertices in contact").c_str() : "");
  }
}

void print_large_drape() {
  ClothGridOptions options;
  options.resolution = 128;
  SpringNetwork cloth = make_cloth_grid(options);
  cloth.V.col(1).array() += 0.8;
  SimulationParams params;
  Collider ground, ball;
  ball.type = ColliderType::sphere;
  ball.center = Eigen::Vector3d(0, 0.25, 0);
  ball.radius = 0.25;
  params.contact.colliders = {ground, ball};
  params.contact.friction = 0.4;
  params.self_collision.on = true;
  Simulation simulation(cloth, {}, params);
  for (int step = 0; step < 60; ++step)
    simulation.step();  // onto the ball, the skirt down to the ground
  PhaseTimes times;
  for (int step = 0; step < 30; ++step) {
    simulation.step();
    times.add(simulation.last_step_timing());
  }
  const double step_ms = median(times.total);
  std::printf(
      "self-collision/128x128 drape  %d vertices in contact  step %.2f ms  detection %.2f ms "
      "(%.1f%%)  response %.2f ms (%.1f%%)\n",
      simulation.self_contact_count(), step_ms, median(times.detection),
      100.0 * median(times.detection) / step_ms, median(times.response),
      100.0 * median(times.response) / step_ms);
}

}  // namespace

void print_self_collision_cost() {
  print_pile();
  print_large_drape();
}

}  // namespace wobble::benchmark

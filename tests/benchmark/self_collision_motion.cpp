#include "self_collision_motion.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "../sim/mesh_crossings.h"
#include "../sim/motion_scenes.h"
#include "median.h"
#include "self_collision_cost.h"
#include "sim/simulation.h"

namespace wobble::benchmark {

namespace {

// How often self-contact held back a vertex's motion in the last step (its "bounded" figure, one
// count for each vertex each time the iterate was bounded), per vertex.
double truncated_share(const Simulation& simulation) {
  const double vertices = static_cast<double>(simulation.positions().rows());
  return simulation.last_step_timing().figure("self-contact", "bounded") / vertices;
}

// Two 96×96 sheets, the upper falling 0.5 m onto the lower: with self-contact against without.
void print_falling_sheets() {
  const int n = 96, frames = 40;
  std::vector<Eigen::Vector3d> path[2];
  std::vector<double> step_ms[2];
  std::vector<double> lowest;  // without: the upper sheet's lowest y, frame by frame
  double truncated = 0.0;
  for (const bool on : {false, true}) {
    const testing::MotionScene scene = testing::falling_sheets_scene(n, on);
    Simulation simulation(scene.network, scene.pins, scene.params);
    for (int frame = 0; frame < frames; ++frame) {
      simulation.step();
      step_ms[on].push_back(simulation.last_step_timing().total_ms);
      path[on].push_back(testing::centroid(simulation.positions(), scene.moving));
      if (!on) {
        double low = 1e300;
        for (const int v : scene.moving)
          low = std::min(low, simulation.positions()(v, 1));
        lowest.push_back(low);
      }
      if (on) truncated = std::max(truncated, truncated_share(simulation));
    }
  }
  // Apart: while the upper sheet's lowest vertex is more than 2 cm above the lower sheet.
  int apart = 0;
  while (apart < frames && lowest[apart] > 0.02)
    ++apart;
  double worst = 0.0;
  for (int frame = 0; frame < apart; ++frame)
    worst = std::max(worst, (path[1][frame] - path[0][frame]).norm());
  const auto median_of = [&](int on) {
    return median(std::vector<double>(step_ms[on].begin() + 1, step_ms[on].begin() + apart));
  };
  std::printf(
      "self-contact/motion two 96x96 sheets, one falling 0.5 m  apart for %d frames  centroid "
      "with against without: %.3f mm at most  (frame %d: y %.4f against %.4f m)  step apart "
      "off %.2f ms  on %.2f ms (%.2fx)  vertices held back: at most %.2f times a vertex a step\n",
      apart, 1000.0 * worst, apart - 1, path[1][apart - 1].y(), path[0][apart - 1].y(),
      median_of(0), median_of(1), median_of(1) / median_of(0), truncated);
  std::fflush(stdout);
}

// The 128×128 pile's top row: how far it has dropped by frames 45 and 90.
void print_pile_drop(const char* solver) {
  const int n = 128;
  double drop[2][2] = {};
  std::vector<double> step_ms[2];
  long crossings = 0;
  double truncated = 0.0;
  for (const bool on : {false, true}) {
    const ThrownPile pile = thrown_pile(n, on, solver);
    Simulation simulation(pile.cloth, {}, pile.params, pile.velocity);
    const auto top = [&] {
      double sum = 0.0;
      for (int column = 0; column < n; ++column)
        sum += simulation.positions()(column, 1);
      return sum / n;
    };
    const double start = top();
    for (int frame = 1; frame <= 90; ++frame) {
      simulation.step();
      step_ms[on].push_back(simulation.last_step_timing().total_ms);
      if (frame == 45) drop[on][0] = start - top();
      if (frame == 90) drop[on][1] = start - top();
      if (on) {
        truncated += truncated_share(simulation) / 90.0;
        if (frame % 10 == 0)
          crossings += testing::count_mesh_crossings(simulation.positions(), pile.cloth.F);
      }
    }
  }
  std::printf(
      "self-contact/motion 128x128 pile %-12s top row dropped by frame 45: %.3f m against "
      "%.3f m (%.0f%%), by frame 90: %.3f against %.3f m (%.0f%%)  step off %.2f ms  on %.2f ms "
      "(%.2fx)  held back %.2f times a vertex a step  crossings with self-contact (every tenth "
      "frame) %ld\n",
      solver, drop[1][0], drop[0][0], 100.0 * drop[1][0] / drop[0][0], drop[1][1], drop[0][1],
      100.0 * drop[1][1] / drop[0][1], median(step_ms[0]), median(step_ms[1]),
      median(step_ms[1]) / median(step_ms[0]), truncated, crossings);
  std::fflush(stdout);
}

// A small sheet on a 10° slope for 1 s: on a pinned sheet (self-contact) and on a plane.
void print_sliding() {
  const double angle = 10.0;
  for (const double friction : {0.0, 0.4}) {
    double slid[2] = {};
    for (const bool on_plane : {true, false}) {
      const testing::MotionScene scene = testing::sliding_sheet_scene(angle, friction, on_plane);
      Simulation simulation(scene.network, scene.pins, scene.params);
      const Eigen::Vector3d start = testing::centroid(simulation.positions(), scene.moving);
      for (int frame = 0; frame < 60; ++frame)
        simulation.step();
      slid[on_plane] = (testing::centroid(simulation.positions(), scene.moving) - start)
                           .dot(testing::slope_direction(angle));
    }
    std::printf(
        "self-contact/motion sheet on a 10-degree slope, friction %.1f  slid in 1 s: on a "
        "sheet %.4f m, on a plane collider %.4f m\n",
        friction, slid[0], slid[1]);
  }
  std::fflush(stdout);
}

}  // namespace

void print_self_collision_motion() {
  print_falling_sheets();
  print_sliding();
  print_pile_drop("local-global");
  print_pile_drop("lbfgs");
}

}  // namespace wobble::benchmark

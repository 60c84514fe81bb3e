#include "self_collision_cost.h"

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
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
    detection.push_back(timing.figure("self-contact", "detection"));
    response.push_back(timing.figure("self-contact", "response"));
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

// A process's resident memory from /proc/self/status (kB): "VmRSS" now or "VmHWM" its peak.
long status_kb(const char* key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::size_t length = std::strlen(key);
  while (std::getline(status, line)) {
    if (line.compare(0, length, key) == 0 && line.size() > length && line[length] == ':')
      return std::stol(line.substr(length + 1));
  }
  return -1;
}

struct PileRun {
  int frames = 0;
  double step_ms = 0, detection_ms = 0, response_ms = 0;
  long peak_kb = 0;  // the peak resident memory the run added to its process
  int contacts = 0;
};

// A free n×n cloth (1 m, no bend springs) standing on its lower edge 5 cm above the ground,
// thrown down at 2.5 m/s with a sideways push of 0.8 m/s: 15 iterations, thickness 5 mm,
// friction 0.4. Up to 90 frames, or fewer when they pass `budget_s` of stepping; in a child
// process of its own, so that its peak memory is its own.
PileRun run_pile(int n, bool on, double budget_s) {
  int channel[2];
  if (pipe(channel) != 0) return {};
  const pid_t child = fork();
  if (child == 0) {
    close(channel[0]);
    const long before_kb = status_kb("VmRSS");
    ClothGridOptions options;
    options.resolution = n;
    options.bend = false;
    SpringNetwork cloth = make_cloth_grid(options);
    for (Eigen::Index i = 0; i < cloth.V.rows(); ++i) {
      cloth.V(i, 1) = 0.55 - cloth.V(i, 2);
      cloth.V(i, 2) = 0.0;
    }
    Eigen::MatrixXd velocity = Eigen::MatrixXd::Zero(cloth.V.rows(), 3);
    velocity.col(0).setConstant(0.8);
    velocity.col(1).setConstant(-2.5);
    SimulationParams params;
    params.k = 1000.0;
    params.dt = 1.0 / 60.0;
    params.iterations = 15;
    params.damping = 0.2;
    params.contact.friction = 0.4;
    params.contact.colliders = {Collider{}};
    params.self_collision.on = on;
    params.self_collision.thickness = 0.005;
    Simulation simulation(cloth, {}, params, velocity);
    PhaseTimes times;
    const auto start = std::chrono::steady_clock::now();
    PileRun run;
    for (run.frames = 0; run.frames < 90; ++run.frames) {
      if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
          budget_s) {
        break;
      }
      simulation.step();
      times.add(simulation.last_step_timing());
    }
    run.step_ms = median(times.total);
    run.detection_ms = median(times.detection);
    run.response_ms = median(times.response);
    run.contacts = simulation.self_contact_count();
    run.peak_kb = status_kb("VmHWM") - before_kb;
    const ssize_t written = write(channel[1], &run, sizeof run);
    _exit(written == static_cast<ssize_t>(sizeof run) ? 0 : 1);
  }
  close(channel[1]);
  PileRun run;
  const bool read_all = child > 0 && read(channel[0], &run, sizeof run) == sizeof run;
  close(channel[0]);
  if (child > 0) waitpid(child, nullptr, 0);
  return read_all ? run : PileRun{};
}

// Free n×n cloths piling on the ground (run_pile), with and without self-collision: median
// step, detection and response, detection per vertex, and peak memory, for n = 40, 128, 256.
void print_piles() {
  for (const int n : {40, 128, 256}) {
    const PileRun off = run_pile(n, false, 60.0);
    const PileRun on = run_pile(n, true, 60.0);
    const double vertices = static_cast<double>(n) * n;
    std::printf(
        "self-collision/%dx%d free pile  %d frames  off %.2f ms  on %.2f ms (%.2fx)  detection "
        "%.2f ms (%.2f us/vertex)  response %.2f ms  peak memory off %.1f MB  on %.1f MB "
        "(%.2fx)  %d vertices in contact\n",
        n, n, on.frames, off.step_ms, on.step_ms, on.step_ms / off.step_ms, on.detection_ms,
        1000.0 * on.detection_ms / vertices, on.response_ms, off.peak_kb / 1024.0,
        on.peak_kb / 1024.0, static_cast<double>(on.peak_kb) / static_cast<double>(off.peak_kb),
        on.contacts);
    std::fflush(stdout);
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
  print_piles();
  print_large_drape();
}

}  // namespace wobble::benchmark

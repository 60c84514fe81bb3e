#include "self_collision_cost.h"

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "../sim/mesh_crossings.h"
#include "io/load_scene.h"
#include "median.h"
#include "sim/contact/self_contact_term.h"
#include "sim/instruments/frame_energy.h"
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
    response.push_back(timing.figure("self-contact", "solve"));
  }
};

// The shipped assets/cloth_pile.json (a 40x40 pleated cloth thrown down edge first, thickness
// 1 cm, 50 iterations), with and without self-contact; 900 steps (15 s). Its pleats fold shut
// within about 30 steps, the layers settle until about step 300, then it lies in a pile: the
// step's median in each phase, and the energy once it lies, against its whole energy at the start
// (a pile that keeps gaining energy shows here, which a short run does not). (Until 28 November
// 2026 it was pleated upright, stood on its edge for about 5 s and fell between steps 300 and
// 500; docs/performance.md's figures before that date are of that pile.)
void print_pile() {
  const Scene scene = load_scene(WOBBLE_ASSETS_DIR "/cloth_pile.json");
  SimulationParams params = scene.params;
  struct Phase {
    const char* name;
    int first, last;
  };
  const Phase phases[] = {{"folding", 0, 29}, {"settling", 30, 299}, {"lying", 700, 899}};
  PhaseTimes times[2][3];
  FrameEnergy start[2], end[2];
  double most[2] = {0.0, 0.0};  // the largest whole energy once it lies (J)
  int contacts = 0;
  for (const bool on : {false, true}) {
    params.self_collision.on = on;
    Simulation simulation(scene.network, scene.pins, params, scene.initial_velocity);
    start[on] = frame_energy(simulation);
    for (int step = 0; step < 900; ++step) {
      simulation.step();
      for (int phase = 0; phase < 3; ++phase) {
        if (step >= phases[phase].first && step <= phases[phase].last)
          times[on][phase].add(simulation.last_step_timing());
      }
      if (step >= 700) most[on] = std::max(most[on], frame_energy(simulation).total);
    }
    end[on] = frame_energy(simulation);
    if (on) contacts = simulation.term<wobble::SelfContactTerm>()->contact_count();
  }
  for (int phase = 0; phase < 3; ++phase) {
    const double off = median(times[0][phase].total), on = median(times[1][phase].total);
    std::printf(
        "self-contact/cloth_pile.json %-8s (steps %d-%d)  off %.2f ms  on %.2f ms "
        "(%.2fx)  detection %.2f ms  solve %.2f ms\n",
        phases[phase].name, phases[phase].first, phases[phase].last, off, on, on / off,
        median(times[1][phase].detection), median(times[1][phase].response));
  }
  for (const bool on : {false, true}) {
    std::printf(
        "self-contact/cloth_pile.json energy, self-contact %-3s  start %.3g J  at step 900: "
        "kinetic %.3g J, springs %.3g J, whole %.3g J  (most over steps 700-899 %.3g J)%s\n",
        on ? "on" : "off", start[on].total, end[on].kinetic, end[on].spring, end[on].total,
        most[on], on ? ("  " + std::to_string(contacts) + " vertices in contact").c_str() : "");
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
  double step_ms = 0, detection_ms = 0, solve_ms = 0, guard_ms = 0;
  long peak_kb = 0;  // the peak resident memory the run added to its process
  int contacts = 0;
  long repairs = 0;         // vertices the crossing guard put back, all frames
  long crossings_last = 0;  // the most edges through triangles in any of the last 10 frames
  long crossings_most = 0;  // the most in any frame
};

// A deterministic number in [−1, 1] for vertex i and a salt.
double jitter(Eigen::Index i, int salt) {
  std::uint64_t h =
      static_cast<std::uint64_t>(i) * 0x9e3779b97f4a7c15ull + salt * 0xbf58476d1ce4e5b9ull;
  h ^= h >> 31;
  h *= 0x94d049bb133111ebull;
  h ^= h >> 29;
  return static_cast<double>(h % 2000001) / 1000000.0 - 1.0;
}

// A free n×n cloth (1 m, no bend springs) standing on its lower edge 5 cm above the ground,
// pleated along x (5 cm deep, 25 cm apart) and jittered across its plane by a fifth of an edge,
// thrown down at 2.5 m/s with a velocity across its plane that varies along it (and jitter), so
// that it buckles and folds over itself into a pile. 15 iterations, thickness 5 mm, friction 0.4,
// damping 0.2 /s. Up to 90 frames, or fewer when they pass `budget_s` of stepping; in a child
// process of its own, so that its peak memory is its own. Crossings are counted
// (tests/sim/mesh_crossings.h) after each of the frames.
PileRun run_pile(int n, bool on, const char* solver, double budget_s) {
  int channel[2];
  if (pipe(channel) != 0) return {};
  const pid_t child = fork();
  if (child == 0) {
    close(channel[0]);
    const long before_kb = status_kb("VmRSS");
    const ThrownPile pile = thrown_pile(n, on, solver);
    const SpringNetwork& cloth = pile.cloth;
    Simulation simulation(cloth, {}, pile.params, pile.velocity);
    PhaseTimes times;
    std::vector<double> guard;
    const auto start = std::chrono::steady_clock::now();
    PileRun run;
    for (run.frames = 0; run.frames < 90; ++run.frames) {
      if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
          budget_s) {
        break;
      }
      simulation.step();
      const StepTiming& timing = simulation.last_step_timing();
      times.add(timing);
      guard.push_back(timing.figure("self-contact", "guard"));
      run.repairs += static_cast<long>(timing.figure("self-contact", "guard repairs"));
      if (run.frames % 10 == 9 || run.frames >= 80) {
        const long crossings = testing::count_mesh_crossings(simulation.positions(), cloth.F);
        run.crossings_most = std::max(run.crossings_most, crossings);
        if (run.frames >= 80) run.crossings_last = std::max(run.crossings_last, crossings);
      }
    }
    run.step_ms = median(times.total);
    run.detection_ms = median(times.detection);
    run.solve_ms = median(times.response);
    run.guard_ms = median(guard);
    run.contacts =
        static_cast<int>(simulation.last_step_timing().figure("self-contact", "contacts"));
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

// Free n×n cloths thrown into piles (run_pile), with and without self-contact: median step,
// the term's detection, solve and guard, detection per vertex, the guard's repairs, crossings
// (without self-contact they show that the pile does fold through itself), peak memory; for
// n = 40, 128 (both solvers) and 256.
void print_piles() {
  struct Case {
    int n;
    const char* solver;
  };
  for (const Case& c : {Case{40, "local-global"}, Case{128, "local-global"}, Case{128, "lbfgs"},
                        Case{256, "local-global"}}) {
    const PileRun off = run_pile(c.n, false, c.solver, 60.0);
    const PileRun on = run_pile(c.n, true, c.solver, 60.0);
    const double vertices = static_cast<double>(c.n) * c.n;
    std::printf(
        "self-contact/%dx%d pile %-12s %d frames  off %.2f ms  on %.2f ms (%.2fx)  detection "
        "%.2f ms (%.3f us/vertex)  solve %.2f ms  guard %.2f ms  guard repairs %ld  crossings "
        "off %ld (last 10 frames %ld)  on %ld (last 10 frames %ld)  peak memory off %.1f MB  on "
        "%.1f MB (%.2fx)  %d vertices in contact\n",
        c.n, c.n, c.solver, on.frames, off.step_ms, on.step_ms, on.step_ms / off.step_ms,
        on.detection_ms, 1000.0 * on.detection_ms / vertices, on.solve_ms, on.guard_ms, on.repairs,
        off.crossings_most, off.crossings_last, on.crossings_most, on.crossings_last,
        off.peak_kb / 1024.0, on.peak_kb / 1024.0,
        static_cast<double>(on.peak_kb) / static_cast<double>(off.peak_kb), on.contacts);
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
      "self-contact/128x128 drape  %d vertices in contact  step %.2f ms  detection %.2f ms "
      "(%.1f%%)  solve %.2f ms (%.1f%%)\n",
      simulation.term<wobble::SelfContactTerm>()->contact_count(), step_ms, median(times.detection),
      100.0 * median(times.detection) / step_ms, median(times.response),
      100.0 * median(times.response) / step_ms);
}

}  // namespace

ThrownPile thrown_pile(int n, bool on, const char* solver) {
  ClothGridOptions options;
  options.resolution = n;
  options.bend = false;
  ThrownPile pile;
  pile.cloth = make_cloth_grid(options);
  SpringNetwork& cloth = pile.cloth;
  const double edge = 1.0 / (n - 1);
  Eigen::MatrixXd& velocity = pile.velocity;
  velocity = Eigen::MatrixXd::Zero(cloth.V.rows(), 3);
  for (Eigen::Index i = 0; i < cloth.V.rows(); ++i) {
    const double x = cloth.V(i, 0), z = cloth.V(i, 2);
    cloth.V(i, 1) = 0.55 - z;
    cloth.V(i, 2) = 0.05 * std::sin(2.0 * pi * x / 0.25) + 0.2 * edge * jitter(i, 1);
    // Buckling across its plane, more the higher up (as tests/sim/folding_scenes.cpp's pile).
    const double height = 0.55 - z;
    velocity(i, 0) = 0.3 * height * std::cos(2.0 * pi * x);
    velocity(i, 1) = -2.5;
    velocity(i, 2) = 1.2 * height * std::sin(3.0 * pi * x + 0.5) + 0.3 * jitter(i, 2);
  }
  SimulationParams& params = pile.params;
  params.k = 1000.0;
  params.dt = 1.0 / 60.0;
  params.iterations = 15;
  params.damping = 0.2;
  params.solver = solver;
  params.contact.friction = 0.4;
  params.contact.colliders = {Collider{}};
  params.self_collision.on = on;
  params.self_collision.thickness = 0.005;
  return pile;
}

void print_self_collision_cost() {
  print_pile();
  print_piles();
  print_large_drape();
}

}  // namespace wobble::benchmark

// The method's guarantee, on every scene Wobble ships: each local-global iteration lowers the
// step's energy (or leaves it), whatever the scene holds: pins, damping, wind, colliders,
// course-format gravity. Scene files are found by listing assets/, so a new one is covered
// without touching this test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "../shared_constants.h"
#include "io/load_scene.h"
#include "shipped_scenes.h"
#include "sim/simulation.h"

namespace {

using wobble::testing::assets;

TEST(EnergyDescent, EveryShippedSceneEveryIteration) {
  const std::vector<std::string> scenes = wobble::testing::shipped_scenes(assets);
  ASSERT_GE(scenes.size(), 12u) << "the built-in scenes and the scene files of assets/";
  for (const std::string& source : scenes) {
    SCOPED_TRACE(source);
    wobble::Scene scene = wobble::load_scene(source);
    scene.params.chebyshev = false;  // the guarantee is the plain iteration's
    // Self-contact's forces are multipliers that grow with each iterate (augmented Lagrangian,
    // sim/contact/self_contact_term.h), and its bounds move iterates back: neither is a descent
    // on the step energy, so the guarantee is the method's without them.
    scene.params.self_collision.on = false;
    wobble::Simulation simulation(scene.network, scene.pins, scene.params, scene.initial_velocity);
    simulation.set_convergence_recording(true);
    // Larger scenes are slower to step; a second of their motion is enough to leave rest.
    const int steps = scene.network.V.rows() > 5000 ? 12 : 60;
    int descending_steps = 0;
    for (int step = 1; step <= steps; ++step) {
      ASSERT_EQ(simulation.step(), wobble::StepStatus::ok) << "step " << step;
      const wobble::ConvergenceTrace& trace = simulation.last_convergence();
      ASSERT_EQ(trace.iterations(), scene.params.iterations);
      for (int i = 1; i <= trace.iterations(); ++i) {
        // 1e-12 relative: the rounding of evaluating a sum of terms of this size.
        ASSERT_LE(trace.energy[i], trace.energy[i - 1] + 1e-12 * std::abs(trace.energy[i - 1]))
            << "step " << step << ", iteration " << i;
      }
      if (trace.energy.back() < trace.energy.front()) ++descending_steps;
    }
    EXPECT_GT(descending_steps, 0) << "the iterations must do something";
  }
}

}  // namespace

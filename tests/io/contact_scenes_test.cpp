// The shipped contact scenes, loaded from assets/ as a user opens them and run over their whole
// demo: no vertex ends any step inside a collider by more than 1% of its size or below the
// ground by more than the contact offset, and each does what its description promises.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "../shared_constants.h"
#include "io/load_scene.h"
#include "sim/contact/collider.h"
#include "sim/contact/collider_contact_term.h"
#include "sim/simulation.h"

namespace {

using wobble::testing::assets;

struct Run {
  double worst_relative = 0.0;      // deepest vertex inside a bounded collider / its scale
  double worst_below_ground = 0.0;  // m
};

// Steps `simulation` `steps` times, recording the worst penetration after every step.
Run run_scene(wobble::Simulation& simulation, int steps) {
  Run run;
  for (int step = 0; step < steps; ++step) {
    EXPECT_EQ(simulation.step(), wobble::StepStatus::ok) << "step " << step;
    const Eigen::MatrixXd& p = simulation.positions();
    for (const wobble::Collider& c : wobble::colliders_in(simulation.terms())) {
      const double scale = wobble::collider_scale(c);
      for (Eigen::Index i = 0; i < p.rows(); ++i) {
        const double depth = -wobble::collider_surface(c, p.row(i).transpose()).distance;
        if (std::isinf(scale)) {
          run.worst_below_ground = std::max(run.worst_below_ground, depth);
        } else {
          run.worst_relative = std::max(run.worst_relative, depth / scale);
        }
      }
    }
  }
  return run;
}

std::unique_ptr<wobble::Simulation> open(const std::string& name) {
  const wobble::Scene scene = wobble::load_scene(assets + "/" + name + ".json");
  EXPECT_FALSE(scene.params.contact.colliders.empty()) << name;
  return std::make_unique<wobble::Simulation>(scene.network, scene.pins, scene.params,
                                              scene.initial_velocity);
}

void expect_no_penetration(const Run& run, const wobble::Simulation& simulation) {
  EXPECT_LE(run.worst_relative, 0.01);
  EXPECT_LE(run.worst_below_ground,
            simulation.term<wobble::ColliderContactTerm>()->colliders().offset());
}

TEST(ContactScenes, DrapeRestsOnTheBall) {
  auto simulation = open("drape");
  expect_no_penetration(run_scene(*simulation, 240), *simulation);
  const Eigen::MatrixXd& p = simulation->positions();
  EXPECT_NEAR(p.col(1).maxCoeff(), 0.8, 0.03) << "the top of the cloth lies on the ball's top";
  EXPECT_LT(p.col(1).minCoeff(), 0.4) << "its corners hang down the sides";
  // Q is refactorized only when the set of vertices near the ball changes: once the cloth rests,
  // never.
  const int factorizations = simulation->numeric_factorizations();
  run_scene(*simulation, 60);
  EXPECT_EQ(simulation->numeric_factorizations(), factorizations);
}

TEST(ContactScenes, TableclothStaysWithFrictionAndSlidesOffWithout) {
  auto held = open("tablecloth");
  expect_no_penetration(run_scene(*held, 300), *held);
  EXPECT_NEAR(held->positions().col(0).mean(), 0.3, 0.1);

  auto slippery = open("tablecloth");
  slippery->apply(wobble::with_setting(slippery->params(), "friction", 0.0));
  expect_no_penetration(run_scene(*slippery, 300), *slippery);
  EXPECT_GT(slippery->positions().col(0).mean(), 0.7) << "it slides off the table's +x side";
}

TEST(ContactScenes, JellyDropComesToRestOnTheFloor) {
  auto simulation = open("jelly_drop");
  EXPECT_DOUBLE_EQ(simulation->params().damping, 1.0);
  expect_no_penetration(run_scene(*simulation, 240), *simulation);  // 4 s
  EXPECT_LT(simulation->velocities().rowwise().norm().maxCoeff(), 0.05);
  EXPECT_NEAR(simulation->positions().col(1).minCoeff(),
              simulation->term<wobble::ColliderContactTerm>()->colliders().offset(), 0.01);
}

TEST(ContactScenes, FlagFliesInTheWindBesideItsPole) {
  auto simulation = open("flag");
  EXPECT_TRUE(simulation->params().wind.on);
  EXPECT_DOUBLE_EQ(simulation->params().gravity.x(), 0.0) << "real wind, not sideways gravity";
  const Eigen::MatrixXd rest = simulation->positions();
  expect_no_penetration(run_scene(*simulation, 180), *simulation);
  // The free edge streams downwind (+x, +z) and keeps moving: it snaps, it does not hang.
  const double free_edge_z = simulation->positions().col(2).maxCoeff();
  EXPECT_GT(free_edge_z, 0.2);
  const double speed = simulation->velocities().rowwise().norm().maxCoeff();
  EXPECT_GT(speed, 0.2);
  EXPECT_GT((simulation->positions() - rest).rowwise().norm().maxCoeff(), 0.3);
}

}  // namespace

// Contact in the stepper: cloth and jelly against colliders, friction, and Q
// refactorized only when the set of vertices near a collider changes.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "sim/contact/collider.h"
#include "sim/contact/collider_contact_term.h"
#include "sim/shapes/cloth_grid.h"
#include "sim/shapes/jelly_block.h"
#include "sim/simulation.h"
#include "test_colliders.h"

namespace {

using wobble::Collider;
using wobble::ColliderType;
using wobble::Simulation;
using wobble::SimulationParams;
using wobble::testing::box_collider;
using wobble::testing::ground_collider;
using wobble::testing::sphere_collider;

// A square cloth of `resolution`² vertices and side `size`, flat at height `height`, centred
// over (x, z).
wobble::SpringNetwork cloth(int resolution, double size, double height, double x = 0.0,
                            double z = 0.0) {
  wobble::ClothGridOptions options;
  options.resolution = resolution;
  options.size = size;
  wobble::SpringNetwork network = wobble::make_cloth_grid(options);
  network.V.col(0).array() += x;
  network.V.col(1).array() += height;
  network.V.col(2).array() += z;
  return network;
}

SimulationParams contact_params(std::vector<Collider> colliders, double friction) {
  SimulationParams params;
  params.k = 1000.0;
  params.iterations = 30;
  params.contact.colliders = std::move(colliders);
  params.contact.friction = friction;
  return params;
}

// How deep the deepest vertex is inside any collider, as a fraction of that collider's scale
// (the ground: in m below it, against the contact offset).
struct Penetration {
  double relative = 0.0;      // sphere, box, capsule: depth / scale
  double below_ground = 0.0;  // m
};

Penetration penetration(const Simulation& simulation) {
  Penetration worst;
  const Eigen::MatrixXd& p = simulation.positions();
  for (const Collider& c : wobble::colliders_in(simulation.terms())) {
    for (Eigen::Index i = 0; i < p.rows(); ++i) {
      const double depth = -wobble::collider_surface(c, p.row(i).transpose()).distance;
      if (c.type == ColliderType::ground || c.type == ColliderType::plane) {
        worst.below_ground = std::max(worst.below_ground, depth);
      } else {
        worst.relative = std::max(worst.relative, depth / wobble::collider_scale(c));
      }
    }
  }
  return worst;
}

// Runs `steps` steps, checking after each that every step succeeded and no vertex is inside a
// collider by more than 1% of its scale, or below the ground by more than the contact offset.
void run_checking_contact(Simulation& simulation, int steps) {
  for (int step = 0; step < steps; ++step) {
    ASSERT_EQ(simulation.step(), wobble::StepStatus::ok) << "step " << step;
    const Penetration worst = penetration(simulation);
    ASSERT_LE(worst.relative, 0.01) << "step " << step;
    ASSERT_LE(worst.below_ground,
              simulation.term<wobble::ColliderContactTerm>()->colliders().offset())
        << "step " << step;
  }
}

TEST(Contact, ClothDrapesOverASphereWithoutEnteringIt) {
  for (const bool chebyshev : {false, true}) {
    SCOPED_TRACE(chebyshev ? "Chebyshev" : "plain");
    SimulationParams params =
        contact_params({ground_collider(), sphere_collider(Eigen::Vector3d(0, 0.5, 0), 0.3)}, 0.3);
    params.chebyshev = chebyshev;
    Simulation simulation(cloth(24, 1.0, 1.0), {}, params);
    run_checking_contact(simulation, 180);
    // It really drapes: the middle rests on the sphere's top, the corners hang below it.
    const Eigen::MatrixXd& p = simulation.positions();
    const int middle = wobble::cloth_grid_vertex(24, 12, 12);
    EXPECT_NEAR(p(middle, 1), 0.8, 0.03);
    EXPECT_LT(p(0, 1), 0.6);
    EXPECT_GT(simulation.term<wobble::ColliderContactTerm>()->colliders().contact_count(), 20);
  }
}

TEST(Contact, WithoutCollidersTheClothFallsThrough) {
  // The check above must be able to fail: the same cloth with no collider ends inside the
  // sphere's place and below the ground.
  Simulation simulation(cloth(24, 1.0, 1.0), {}, contact_params({}, 0.3));
  for (int step = 0; step < 20; ++step)
    simulation.step();
  const Collider ball = sphere_collider(Eigen::Vector3d(0, 0.5, 0), 0.3);
  double deepest = 0.0;
  for (Eigen::Index i = 0; i < simulation.positions().rows(); ++i) {
    deepest = std::max(
        deepest,
        -wobble::collider_surface(ball, simulation.positions().row(i).transpose()).distance);
  }
  EXPECT_GT(deepest, 0.1);
}

TEST(Contact, RefactorizesQOnlyWhenTheContactSetChanges) {
  // Contact inside the solve puts its weight on Q's diagonal for the vertices near a collider:
  // Q's values change as the cloth comes down (its pattern never), and not while it lies there.
  Simulation simulation(cloth(16, 1.0, 1.0), {}, contact_params({ground_collider(0.5)}, 0.5));
  const int before = simulation.numeric_factorizations();
  for (int step = 0; step < 60; ++step)
    simulation.step();
  const int landed = simulation.numeric_factorizations();
  EXPECT_GT(landed, before) << "the vertices near the ground join the solve's contact";
  for (int step = 0; step < 60; ++step)
    simulation.step();
  EXPECT_GT(simulation.term<wobble::ColliderContactTerm>()->colliders().contact_count(), 100)
      << "the cloth must be lying on the ground";
  EXPECT_EQ(simulation.numeric_factorizations(), landed);
  EXPECT_EQ(simulation.symbolic_analyses(), 1);
}

TEST(Contact, APinDraggedThroughASphereNeverLeavesVerticesInside) {
  const Eigen::Vector3d center(0.0, 0.6, 0.0);
  Simulation simulation(cloth(20, 0.6, 1.2, 0.0, -0.8), {0, 19},
                        contact_params({sphere_collider(center, 0.25)}, 0.2));
  // Pull both pins down through the sphere's middle and out below it, in 2 s.
  const int steps = 120;
  const Eigen::Vector3d start0 = simulation.pin_target(0), start19 = simulation.pin_target(19);
  const Eigen::Vector3d travel(0.0, -1.1, 0.8);
  for (int step = 0; step < steps; ++step) {
    const double t = std::min(1.0, (step + 1.0) / (0.75 * steps));
    simulation.set_pin_target(0, start0 + t * travel);
    simulation.set_pin_target(19, start19 + t * travel);
    ASSERT_EQ(simulation.step(), wobble::StepStatus::ok) << "step " << step;
    ASSERT_LE(penetration(simulation).relative, 0.01) << "step " << step;
  }
  // The pins went through while the sphere held their vertices out: they came out below.
  EXPECT_LT(simulation.positions()(0, 1), center.y() - 0.25);
}

TEST(Contact, FrictionHoldsATableclothThatSlidesOffWithoutIt) {
  // A cloth 1.6 m square dropped onto a 1.2 × 0.8 table top, shifted 0.3 m along +x so that far
  // more hangs on one side.
  auto run = [](double friction) {
    const Collider table = box_collider(Eigen::Vector3d(0, 0.4, 0), Eigen::Vector3d(1.2, 0.8, 0.8));
    SimulationParams params = contact_params({ground_collider(), table}, friction);
    Simulation simulation(cloth(32, 1.6, 0.85, 0.3), {}, params);
    for (int step = 0; step < 300; ++step) {
      EXPECT_EQ(simulation.step(), wobble::StepStatus::ok);
    }
    return simulation.positions().col(0).mean();
  };
  const double held = run(1.0), slid = run(0.0);
  EXPECT_LT(std::abs(held - 0.3), 0.1) << "with friction the cloth stays on the table";
  EXPECT_GT(slid, 0.3 + 0.4) << "without friction it slides off";
}

TEST(Contact, AJellyDroppedOnTheGroundComesToRest) {
  wobble::JellyBlockOptions options;
  wobble::SpringNetwork jelly = wobble::make_jelly_block(options);
  jelly.V.col(1).array() += 0.3;
  SimulationParams params = contact_params({ground_collider()}, 0.5);
  params.k = 5000.0;  // a firm jelly: at 1500 N/m it spreads to 1.4 times its width
  params.damping = 1.0;
  params.iterations = 50;
  Simulation simulation(jelly, {}, params);
  const Eigen::Vector3d rest_extent = jelly.V.colwise().maxCoeff() - jelly.V.colwise().minCoeff();
  run_checking_contact(simulation, 240);  // 4 s
  const double top_speed = simulation.velocities().rowwise().norm().maxCoeff();
  EXPECT_LT(top_speed, 0.05);
  // Resting on the ground, neither sunk into it nor blown apart.
  const Eigen::MatrixXd& p = simulation.positions();
  EXPECT_NEAR(p.col(1).minCoeff(),
              simulation.term<wobble::ColliderContactTerm>()->colliders().offset(), 0.01);
  const Eigen::Vector3d extent = p.colwise().maxCoeff() - p.colwise().minCoeff();
  // (It sags about a quarter under its own weight: 0.5 m tall, it rests 0.38 m tall.)
  EXPECT_LT((extent - rest_extent).cwiseAbs().maxCoeff(), 0.3 * rest_extent.maxCoeff());
}

TEST(Contact, ResetPutsMovedCollidersBack) {
  Simulation simulation(cloth(8, 1.0, 1.0), {},
                        contact_params({sphere_collider({0, 0, 0}, 0.2)}, 0.0));
  simulation.term<wobble::ColliderContactTerm>()->translate(0, Eigen::Vector3d(0.5, 0, 0));
  EXPECT_DOUBLE_EQ(wobble::colliders_in(simulation.terms())[0].center.x(), 0.5);
  simulation.reset();
  EXPECT_DOUBLE_EQ(wobble::colliders_in(simulation.terms())[0].center.x(), 0.0);
  EXPECT_THROW(
      simulation.term<wobble::ColliderContactTerm>()->translate(1, Eigen::Vector3d::Zero()),
      std::out_of_range);
}

TEST(Contact, ATermOfOtherSettingsChangingKeepsWhatContactHas) {
  // Collider contact is made by its factory like any term, but not made again when other
  // settings change: the collider stays where it was dragged and the cloth lying on it stays in
  // contact through a change of the wind (which makes the wind anew) and of friction (read each
  // step from the context).
  Simulation simulation(cloth(8, 1.0, 0.3), {}, contact_params({ground_collider()}, 0.0));
  auto* contact = simulation.term<wobble::ColliderContactTerm>();
  ASSERT_NE(contact, nullptr);
  for (int step = 0; step < 40; ++step)
    simulation.step();
  ASSERT_GT(contact->colliders().contact_count(), 0) << "the cloth lies on the ground";
  contact->translate(0, Eigen::Vector3d(0.0, 0.01, 0.0));
  SimulationParams windy = simulation.params();
  windy.wind.on = true;
  windy.contact.friction = 0.5;
  simulation.apply(windy);
  EXPECT_EQ(simulation.term<wobble::ColliderContactTerm>(), contact) << "the same term";
  EXPECT_DOUBLE_EQ(wobble::colliders_in(simulation.terms())[0].height, 0.01);
  EXPECT_GT(contact->colliders().contact_count(), 0);
  simulation.step();
  EXPECT_EQ(contact->colliders().friction(), 0.5);
  // A scene without colliders has no collider contact at all.
  Simulation free(cloth(4, 1.0, 1.0), {}, SimulationParams{});
  EXPECT_EQ(free.term<wobble::ColliderContactTerm>(), nullptr);
  EXPECT_TRUE(wobble::colliders_in(free.terms()).empty());
}

TEST(Contact, AMovingBoxCarriesAClothLyingOnItByFriction) {
  const Collider plate = box_collider(Eigen::Vector3d(0, 0.45, 0), Eigen::Vector3d(1.5, 0.1, 1.5));
  auto run = [&](double friction) {
    Simulation simulation(cloth(12, 0.6, 0.55), {}, contact_params({plate}, friction));
    for (int step = 0; step < 30; ++step)
      simulation.step();  // settle on the plate
    const double before = simulation.positions().col(0).mean();
    for (int step = 0; step < 30; ++step) {
      simulation.term<wobble::ColliderContactTerm>()->translate(0, Eigen::Vector3d(0.005, 0, 0));
      simulation.step();
    }
    return simulation.positions().col(0).mean() - before;
  };
  EXPECT_GT(run(2.0), 0.1);             // carried most of the 0.15 m
  EXPECT_LT(std::abs(run(0.0)), 0.01);  // slips on a frictionless plate
}

}  // namespace

#ifndef WOBBLE_TESTS_IO_SAVED_SCENE_CHECKS_H
#define WOBBLE_TESTS_IO_SAVED_SCENE_CHECKS_H

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <filesystem>
#include <set>

#include "sim/scene.h"
#include "sim/simulation.h"

namespace wobble::testing {

// Same shape and every entry the same double (or int): a saved scene must read back bit for bit.
template <typename A, typename B>
bool same_matrix(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() && (a.array() == b.array()).all();
}

// The keys a collider of its type has in a scene file. The others mean nothing for its type,
// and translate_collider moves them all, so they are not compared.
inline void expect_same_collider(const Collider& a, const Collider& b) {
  ASSERT_EQ(a.type, b.type);
  switch (a.type) {
    case ColliderType::ground:
      EXPECT_EQ(a.height, b.height);
      break;
    case ColliderType::plane:
      EXPECT_TRUE(same_matrix(a.center, b.center));
      EXPECT_TRUE(same_matrix(a.normal, b.normal))
          << a.normal.transpose() << " vs " << b.normal.transpose();
      break;
    case ColliderType::sphere:
      EXPECT_TRUE(same_matrix(a.center, b.center));
      EXPECT_EQ(a.radius, b.radius);
      break;
    case ColliderType::box:
      EXPECT_TRUE(same_matrix(a.center, b.center));
      EXPECT_TRUE(same_matrix(a.size, b.size));
      break;
    case ColliderType::capsule:
      EXPECT_TRUE(same_matrix(a.from, b.from));
      EXPECT_TRUE(same_matrix(a.to, b.to));
      EXPECT_EQ(a.radius, b.radius);
      break;
  }
  EXPECT_EQ(a.friction, b.friction);
}

// Every SimulationParams field, one by one, so that a field the writer drops is named.
inline void expect_same_params(const SimulationParams& a, const SimulationParams& b) {
  EXPECT_EQ(a.k, b.k);
  EXPECT_EQ(a.dt, b.dt);
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_TRUE(same_matrix(a.gravity, b.gravity));
  EXPECT_EQ(a.gravity_model, b.gravity_model);
  EXPECT_EQ(a.first_iterate, b.first_iterate);
  EXPECT_EQ(a.chebyshev, b.chebyshev);
  EXPECT_EQ(a.solver, b.solver);
  EXPECT_EQ(a.single_precision_solve_above, b.single_precision_solve_above);
  EXPECT_EQ(a.damping, b.damping);
  EXPECT_EQ(a.wind.on, b.wind.on);
  EXPECT_EQ(a.wind.model, b.wind.model);
  EXPECT_TRUE(same_matrix(a.wind.velocity, b.wind.velocity));
  EXPECT_EQ(a.wind.drag, b.wind.drag);
  EXPECT_EQ(a.wind.lift, b.wind.lift);
  EXPECT_EQ(a.wind.gusts, b.wind.gusts);
  EXPECT_EQ(a.wind.air_density, b.wind.air_density);
  EXPECT_EQ(a.contact.friction, b.contact.friction);
  EXPECT_EQ(a.contact.offset, b.contact.offset);
  EXPECT_EQ(a.self_collision.on, b.self_collision.on);
  // Off, the format keeps no thickness: a scene read back has the default.
  if (a.self_collision.on) {
    EXPECT_EQ(a.self_collision.thickness, b.self_collision.thickness);
  }
  ASSERT_EQ(a.contact.colliders.size(), b.contact.colliders.size());
  for (std::size_t c = 0; c < a.contact.colliders.size(); ++c) {
    SCOPED_TRACE("collider " + std::to_string(c));
    expect_same_collider(a.contact.colliders[c], b.contact.colliders[c]);
  }
}

// `saved` is `original` written and read back: the same network, pins, parameters, initial
// velocity and look (the texture may be named by another path to the same file).
inline void expect_same_scene(const Scene& original, const Scene& saved) {
  EXPECT_EQ(original.name, saved.name);
  EXPECT_EQ(original.description, saved.description);
  EXPECT_TRUE(same_matrix(original.network.V, saved.network.V)) << "V";
  EXPECT_TRUE(same_matrix(original.network.E, saved.network.E)) << "E";
  EXPECT_TRUE(same_matrix(original.network.F, saved.network.F)) << "F";
  EXPECT_TRUE(same_matrix(original.network.m, saved.network.m)) << "m";
  EXPECT_EQ(std::set<int>(original.pins.begin(), original.pins.end()),
            std::set<int>(saved.pins.begin(), saved.pins.end()));
  expect_same_params(original.params, saved.params);
  EXPECT_TRUE(same_matrix(original.initial_velocity, saved.initial_velocity)) << "initial velocity";
  EXPECT_TRUE(same_matrix(original.look.uv, saved.look.uv)) << "uv";
  EXPECT_EQ(original.look.front_color, saved.look.front_color);
  EXPECT_EQ(original.look.back_color, saved.look.back_color);
  EXPECT_EQ(original.look.camera_position, saved.look.camera_position);
  EXPECT_EQ(original.look.camera_target, saved.look.camera_target);
  EXPECT_EQ(original.look.texture.empty(), saved.look.texture.empty());
  if (!original.look.texture.empty() && !saved.look.texture.empty()) {
    EXPECT_TRUE(std::filesystem::equivalent(original.look.texture, saved.look.texture));
  }
}

// Simulations started from both scenes reach bit-identical positions after `steps` steps.
inline void expect_same_steps(const Scene& original, const Scene& saved, int steps) {
  Simulation a(original.network, original.pins, original.params, original.initial_velocity);
  Simulation b(saved.network, saved.pins, saved.params, saved.initial_velocity);
  for (int step = 0; step < steps; ++step) {
    ASSERT_EQ(a.step(), StepStatus::ok);
    ASSERT_EQ(b.step(), StepStatus::ok);
  }
  EXPECT_TRUE(same_matrix(a.positions(), b.positions()))
      << "largest difference " << (a.positions() - b.positions()).cwiseAbs().maxCoeff();
}

}  // namespace wobble::testing

#endif

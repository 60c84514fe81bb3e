// RightSide on its own, beside a left simulation it is handed: --compare's settings on the
// right, everything else copied from the left, its own dt's steps for the left's time, the
// panel's sliders applied to it alone, and Reset back to the left's state.
#include "app/viewer/right_side.h"

#include <gtest/gtest.h>

#include "app/cli/compare_settings.h"
#include "sim/shapes/builtin_scenes.h"

namespace {

TEST(RightSide, ComparesItsOwnSettingsAndCopiesTheRestFromTheLeft) {
  const wobble::Scene scene = wobble::make_builtin_scene("cloth");
  wobble::Simulation left(scene.network, scene.pins, scene.params);
  wobble::RightSide right("");
  EXPECT_FALSE(right.wants_student());
  right.start_compare(scene, left, wobble::parse_compare_settings("iterations=5,dt=0.008"));
  ASSERT_NE(right.simulation(), nullptr);
  EXPECT_TRUE(right.split_asked()) << "the section shows the split";
  EXPECT_EQ(right.simulation()->params().iterations, 5);
  EXPECT_EQ(right.simulation()->params().dt, 0.008);
  EXPECT_EQ(right.simulation()->params().k, left.params().k) << "not compared: the left's";

  // The environment follows the left side; its own settings do not.
  left.apply(wobble::with_setting(left.params(), "damping", 0.5));
  left.apply(wobble::with_setting(left.params(), "k", 900.0));
  left.step();
  right.advance(left, left.params().dt);
  EXPECT_EQ(right.simulation()->params().damping, 0.5);
  EXPECT_EQ(right.simulation()->params().k, scene.params.k);
  // Its own dt's steps for the left's time: 1/60 s is two steps of 8 ms (the third is due next).
  EXPECT_EQ(right.simulation()->steps_taken(), 2);

  right.reset(scene, left);
  EXPECT_EQ(right.simulation()->positions(), left.positions());
  EXPECT_EQ(right.simulation()->steps_taken(), 0);

  right.stop();
  EXPECT_EQ(right.simulation(), nullptr);
}

TEST(RightSide, SettingsReadBackWhatItCompares) {
  const wobble::Scene scene = wobble::make_builtin_scene("cloth");
  wobble::Simulation left(scene.network, scene.pins, scene.params);
  wobble::RightSide right("");
  right.start_compare(scene, left,
                      wobble::parse_compare_settings("solver=lbfgs,iterations=7,k=2000"));
  const wobble::CompareSettings settings = right.settings();
  EXPECT_EQ(settings.choice("solver"), "lbfgs");
  EXPECT_EQ(settings.number("iterations"), 7.0);
  EXPECT_EQ(settings.number("k"), 2000.0);
  // A split view that stays split on a new scene starts from these: the same settings again.
  wobble::RightSide again("");
  again.start_compare(scene, left, settings);
  EXPECT_EQ(again.simulation()->params().solver, "lbfgs");
  EXPECT_EQ(again.simulation()->params().iterations, 7);
  EXPECT_EQ(again.simulation()->params().k, 2000.0);
}

}  // namespace

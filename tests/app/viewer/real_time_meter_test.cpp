#include "app/viewer/real_time_meter.h"

#include <gtest/gtest.h>

namespace {

// A made-up run at 60 frames a wall-clock second.
struct MadeUpRun {
  wobble::RealTimeMeter meter;
  double wall = 0.0, simulated = 0.0;
  long steps = 0;

  // `seconds` of frames, each taking one step of `step` seconds (none when `step` is 0: paused).
  void frames(double seconds, double step) {
    for (int frame = 0; frame < static_cast<int>(seconds * 60.0); ++frame) {
      wall += 1.0 / 60.0;
      if (step > 0.0) {
        simulated += step;
        steps += 1;
      }
      meter.record(wall, simulated, steps);
    }
  }
};

TEST(RealTimeMeter, IsOneWhenEachFrameSimulatesItsOwnDuration) {
  MadeUpRun run;
  EXPECT_EQ(run.meter.real_time_factor(), 0.0);
  run.frames(3.0, 1.0 / 60.0);
  EXPECT_NEAR(run.meter.real_time_factor(), 1.0, 1e-9);
  EXPECT_NEAR(run.meter.steps_per_second(), 60.0, 1e-6);
}

TEST(RealTimeMeter, FollowsTheLastSecondOnly) {
  MadeUpRun run;
  run.frames(3.0, 1.0 / 60.0);
  // Frames now take twice as long as the step they simulate: slow motion at half speed.
  run.frames(2.0, 1.0 / 120.0);
  EXPECT_NEAR(run.meter.real_time_factor(), 0.5, 1e-9);
  EXPECT_NEAR(run.meter.steps_per_second(), 60.0, 1e-6);
}

TEST(RealTimeMeter, PausedIsZeroAndAResetStartsAgain) {
  MadeUpRun run;
  run.frames(2.0, 1.0 / 60.0);
  run.frames(2.0, 0.0);
  EXPECT_EQ(run.meter.real_time_factor(), 0.0);
  EXPECT_EQ(run.meter.steps_per_second(), 0.0);
  // A reset: time and steps go back to 0, and the figures cover only what follows.
  run.frames(2.0, 1.0 / 60.0);
  run.simulated = 0.0;
  run.steps = 0;
  run.frames(0.5, 1.0 / 30.0);
  EXPECT_NEAR(run.meter.real_time_factor(), 2.0, 1e-9);
  EXPECT_NEAR(run.meter.steps_per_second(), 60.0, 1e-6);
}

}  // namespace

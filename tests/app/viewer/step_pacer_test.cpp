#include "app/viewer/step_pacer.h"

#include <gtest/gtest.h>

namespace {

constexpr double frame = 1.0 / 60.0;

// Frames at `frame_seconds` apart for `seconds`; returns the steps handed out.
long run(wobble::StepPacer& pacer, double& now, double seconds, double frame_seconds, double dt,
         double step_seconds, int* most = nullptr) {
  long steps = 0;
  for (double end = now + seconds; now < end - 1e-12; now += frame_seconds) {
    const int due = pacer.steps_due(now, dt, step_seconds, frame);
    if (most != nullptr && due > *most) *most = due;
    steps += due;
  }
  return steps;
}

TEST(StepPacer, KeepsTheSimulatedClockWithTheWallClockWhenStepsAreFast) {
  // dt a quarter of a frame: four steps a frame, 240 a second.
  wobble::StepPacer pacer;
  double now = 0.0;
  int most = 0;
  const long steps = run(pacer, now, 2.0, frame, frame / 4.0, 0.001, &most);
  EXPECT_NEAR(static_cast<double>(steps), 480.0, 4.0);
  EXPECT_EQ(most, 4);
}

TEST(StepPacer, TakesNoStepWhileTheSimulationIsAhead) {
  // dt twice a frame: a step every other frame.
  wobble::StepPacer pacer;
  EXPECT_EQ(pacer.steps_due(0.0, 2.0 * frame, 0.001, frame), 1);  // the first at once
  EXPECT_EQ(pacer.steps_due(frame, 2.0 * frame, 0.001, frame), 0);
  EXPECT_EQ(pacer.steps_due(2.0 * frame, 2.0 * frame, 0.001, frame), 1);
  double now = 3.0 * frame;
  EXPECT_NEAR(static_cast<double>(run(pacer, now, 1.0, frame, 2.0 * frame, 0.001)), 30.0, 1.0);
}

TEST(StepPacer, TakesOnlyWhatFitsInAFrameAndDropsTheRest) {
  // Steps of 6 ms with dt = 2 ms: two fit in a 16.7 ms frame, where real time needs 8.3; the
  // rest is slow motion, and what was not taken is never made up in a burst later.
  wobble::StepPacer pacer;
  double now = 0.0;
  int most = 0;
  const long slow = run(pacer, now, 1.0, frame, 0.002, 0.006, &most);
  EXPECT_EQ(most, 2);
  EXPECT_NEAR(static_cast<double>(slow), 120.0, 2.0);
  // The machine frees up: steps of 0.1 ms. Real time from here on (500 steps a second), with
  // nothing of the lost time caught up.
  most = 0;
  const long fast = run(pacer, now, 1.0, frame, 0.002, 0.0001, &most);
  EXPECT_NEAR(static_cast<double>(fast), 500.0, 10.0);
  EXPECT_LE(most, 9);
}

TEST(StepPacer, AStepSlowerThanAFrameIsOneAFrame) {
  wobble::StepPacer pacer;
  double now = 0.0;
  int most = 0;
  // A frame every 100 ms (the UI waits for nothing, the steps take that long).
  EXPECT_EQ(run(pacer, now, 1.0, 0.1, frame, 0.1, &most), 10);
  EXPECT_EQ(most, 1);
}

TEST(StepPacer, NeverMoreThanTheCap) {
  wobble::StepPacer pacer;
  EXPECT_EQ(pacer.steps_due(0.0, 1e-6, 1e-9, frame), 1);
  EXPECT_EQ(pacer.steps_due(1.0, 1e-6, 1e-9, frame), wobble::StepPacer::max_steps_per_frame);
}

TEST(StepPacer, RestartsItsClock) {
  wobble::StepPacer pacer;
  EXPECT_EQ(pacer.steps_due(0.0, frame, 0.001, frame), 1);
  // Paused for 10 s: playing again takes one step, not a burst.
  pacer.restart();
  EXPECT_EQ(pacer.steps_due(10.0, frame, 0.001, frame), 1);
  EXPECT_EQ(pacer.steps_due(10.0 + 0.5 * frame, frame, 0.001, frame), 0);
}

}  // namespace

#include "app/viewer/moving_median.h"

#include <gtest/gtest.h>

namespace {

TEST(MovingMedian, OneSlowStepDoesNotMoveIt) {
  wobble::MovingMedian median;
  EXPECT_EQ(median.median(), 0.0f);
  for (int i = 0; i < 10; ++i)
    median.add(2.0f);
  median.add(800.0f);
  EXPECT_EQ(median.median(), 2.0f);
  median.clear();
  median.add(3.0f);
  EXPECT_EQ(median.median(), 3.0f);
}

TEST(MovingMedian, FollowsALastingChangeAndForgetsOldValues) {
  wobble::MovingMedian median;
  for (int i = 0; i < wobble::MovingMedian::capacity; ++i)
    median.add(1.0f);
  for (int i = 0; i < wobble::MovingMedian::capacity / 2 + 1; ++i)
    median.add(5.0f);
  EXPECT_EQ(median.median(), 5.0f) << "more than half the window is now 5";
  median.add(1.0f);
  for (int i = 0; i < 3; ++i)
    median.add(7.0f);
  EXPECT_EQ(median.median(), 5.0f);
}

}  // namespace

#include "render/pin_mark_sizes.h"

#include <gtest/gtest.h>

#include <vector>

namespace {

using wobble::PinMarkRule;
using wobble::PinMarkSizes;

std::vector<float> diameters(const std::vector<float>& screen, const PinMarkRule& rule = {}) {
  PinMarkSizes sizes;
  return sizes.compute(screen.data(), static_cast<int>(screen.size() / 2), rule);
}

TEST(PinMarkSizes, SparsePinsKeepTheLargestSize) {
  // A cloth's two pinned corners, hundreds of pixels apart, and a lone pin.
  for (float d : diameters({100, 100, 500, 120}))
    EXPECT_FLOAT_EQ(d, 10.0f);
  EXPECT_EQ(diameters({3, 4}), std::vector<float>{10.0f});
  EXPECT_TRUE(diameters({}).empty());
}

TEST(PinMarkSizes, DensePinsShrinkToAShareOfTheirSpacing) {
  // A rail of pins 8 px apart: 0.8 × 8 = 6.4 px, leaving 1.6 px between neighbours.
  std::vector<float> rail;
  for (int i = 0; i < 20; ++i) {
    rail.push_back(300.0f + 8.0f * i);
    rail.push_back(200.0f);
  }
  for (float d : diameters(rail))
    EXPECT_NEAR(d, 6.4f, 1e-5f);  // float arithmetic on exact inputs
}

TEST(PinMarkSizes, NeverBelowTheSmallest) {
  // Pins 2 px apart (or on top of each other) would vanish: they stay 3 px and touch.
  for (float d : diameters({0, 0, 2, 0, 2, 0}))
    EXPECT_FLOAT_EQ(d, 3.0f);
}

TEST(PinMarkSizes, EachPinAnswersToItsOwnNearestNeighbour) {
  // Two close pins and one far off: the far one keeps its size.
  const std::vector<float> d = diameters({10, 10, 10, 15, 400, 10});
  EXPECT_FLOAT_EQ(d[0], 4.0f);
  EXPECT_FLOAT_EQ(d[1], 4.0f);
  EXPECT_FLOAT_EQ(d[2], 10.0f);
}

TEST(PinMarkSizes, NeighboursAcrossCellBordersAndNegativeCoordinatesCount) {
  // The grid's cells are 10 / 0.8 = 12.5 px wide: one pair straddles the border at 0, the other
  // the one at -12.5.
  const std::vector<float> d = diameters({-3, 5, 3, 5, -10, 40, -15, 40});
  EXPECT_NEAR(d[0], 4.8f, 1e-5f);
  EXPECT_NEAR(d[1], 4.8f, 1e-5f);
  EXPECT_NEAR(d[2], 4.0f, 1e-5f);
  EXPECT_NEAR(d[3], 4.0f, 1e-5f);
}

TEST(PinMarkSizes, TheRuleScalesWithThePixelRatio) {
  PinMarkRule rule;
  rule.largest *= 2.0f;
  rule.smallest *= 2.0f;
  EXPECT_FLOAT_EQ(diameters({0, 0, 100, 0}, rule)[0], 20.0f);
  EXPECT_NEAR(diameters({0, 0, 16, 0}, rule)[0], 12.8f, 1e-5f);
}

}  // namespace

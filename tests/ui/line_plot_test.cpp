// Where line_plot puts its legend: in rows above the curves' frame, never over it, inside the
// plot's own rectangle and with no two entries on top of each other.
#include "ui/line_plot.h"
#include "ui/instrument_windows.h"

#include <gtest/gtest.h>

#include <vector>

namespace {

bool overlap(const ImVec2& a_min, const ImVec2& a_max, const ImVec2& b_min, const ImVec2& b_max) {
  return a_min.x < b_max.x && b_min.x < a_max.x && a_min.y < b_max.y && b_min.y < a_max.y;
}

struct Case {
  float width, height;
};

class LegendLayout : public ::testing::TestWithParam<Case> {};

TEST_P(LegendLayout, TheLegendLiesOutsideTheCurvesFrame) {
  const Case plot = GetParam();
  const float line = 13.0f;  // the default font
  // The energy window's four names ("kinetic 0.07407 J", ...), 7 pixels a character.
  const std::vector<float> names = {119.0f, 112.0f, 112.0f, 98.0f};
  const ImVec2 origin(900.0f, 440.0f), size(plot.width, plot.height);
  const wobble::PlotLayout layout = wobble::plot_layout(origin, size, line, names);
  ASSERT_EQ(layout.legend.size(), names.size());
  ASSERT_LT(layout.area_min.y, layout.area_max.y) << "room left for the curves";
  for (std::size_t i = 0; i < names.size(); ++i) {
    const ImVec2 a = layout.legend[i];
    const ImVec2 b(a.x + wobble::legend_width(names[i], line), a.y + line);
    EXPECT_FALSE(overlap(a, b, layout.area_min, layout.area_max))
        << "entry " << i << " covers the curves";
    EXPECT_GE(a.x, origin.x);
    EXPECT_GE(a.y, origin.y);
    EXPECT_LE(b.x, origin.x + size.x) << "entry " << i;
    for (std::size_t j = 0; j < i; ++j) {
      const ImVec2 c = layout.legend[j];
      const ImVec2 d(c.x + wobble::legend_width(names[j], line), c.y + line);
      EXPECT_FALSE(overlap(a, b, c, d)) << "entries " << j << " and " << i;
    }
  }
}

// The energy window at 1280 × 720 (its column is 380 wide), a wide one, and a narrow one where
// each name takes a row.
INSTANTIATE_TEST_SUITE_P(Sizes, LegendLayout,
                         ::testing::Values(Case{364.0f, 210.0f}, Case{900.0f, 300.0f},
                                           Case{220.0f, 260.0f}));

TEST(LegendLayout, NoNamesLeaveTheWholeHeightToTheCurves) {
  const wobble::PlotLayout named =
      wobble::plot_layout(ImVec2(0, 0), ImVec2(300, 200), 13.0f, {80.0f});
  const wobble::PlotLayout plain = wobble::plot_layout(ImVec2(0, 0), ImVec2(300, 200), 13.0f, {});
  EXPECT_TRUE(plain.legend.empty());
  EXPECT_FLOAT_EQ(named.area_min.y - plain.area_min.y, 13.0f) << "one row of legend";
}

}  // namespace

// The energy legend's numbers keep their digits as the values move: one number of decimals for
// all, from the largest (with %.4g, "0.002569" beside "1.795", then "0.01" a frame later).
TEST(InstrumentWindows, LegendNumbersKeepTheirDigits) {
  EXPECT_EQ(wobble::legend_number(1.795, 1.8132), "1.795");
  EXPECT_EQ(wobble::legend_number(0.002569, 1.8132), "0.003");
  EXPECT_EQ(wobble::legend_number(0.01626, 1.8132), "0.016");
  EXPECT_EQ(wobble::legend_number(0.0100, 1.8132).size(),
            wobble::legend_number(0.0149, 1.79).size());
  EXPECT_EQ(wobble::legend_number(2816.78, 2816.78), "2817");
  EXPECT_EQ(wobble::legend_number(0.00012, 0.00031), "0.0001200");
  EXPECT_EQ(wobble::legend_number(0.0, 0.0), "0.000");
}

#include "app/interaction/view_framing.h"

#include <gtest/gtest.h>

namespace {

TEST(ViewFraming, ThePartRightOfAPanelOnTheLeft) {
  const wobble::ViewportRegion region = wobble::region_beside_panel(1280.0f, 10.0f, 340.0f);
  EXPECT_FLOAT_EQ(region.left, 340.0f / 1280.0f);
  EXPECT_FLOAT_EQ(region.right, 1.0f);
  EXPECT_FLOAT_EQ(region.top, 0.0f);
  EXPECT_FLOAT_EQ(region.bottom, 1.0f);
}

TEST(ViewFraming, ThePartLeftOfAPanelMovedToTheRight) {
  const wobble::ViewportRegion region = wobble::region_beside_panel(1280.0f, 900.0f, 1230.0f);
  EXPECT_FLOAT_EQ(region.left, 0.0f);
  EXPECT_FLOAT_EQ(region.right, 900.0f / 1280.0f);
}

TEST(ViewFraming, TheWholeViewWithoutAPanelOrWhenItLeavesOnlyASliver) {
  const auto whole = [](const wobble::ViewportRegion& region) {
    return region.left == 0.0f && region.right == 1.0f && region.top == 0.0f &&
           region.bottom == 1.0f;
  };
  EXPECT_TRUE(whole(wobble::region_beside_panel(1280.0f, 0.0f, 0.0f)));
  // 400 px wide: the panel leaves 60 px, less than a quarter.
  EXPECT_TRUE(whole(wobble::region_beside_panel(400.0f, 10.0f, 340.0f)));
  EXPECT_FALSE(whole(wobble::region_beside_panel(640.0f, 10.0f, 340.0f)));
}

TEST(ViewFraming, RoomToMoveReachesTheGroundAndAQuarterToEachSide) {
  Eigen::Vector3f lower(-0.5f, 1.0f, -0.5f), upper(0.5f, 1.0f, 0.5f);  // a flat cloth
  wobble::add_room_to_move(lower, upper, -0.2f);
  EXPECT_TRUE(lower.isApprox(Eigen::Vector3f(-0.75f, -0.2f, -0.75f)));
  EXPECT_TRUE(upper.isApprox(Eigen::Vector3f(0.75f, 1.0f, 0.75f)));
  // A shape under the ground (fallen through, or the grid placed above it) keeps its own bottom.
  lower = Eigen::Vector3f(0, -1, 0);
  upper = Eigen::Vector3f(1, 0, 1);
  wobble::add_room_to_move(lower, upper, 0.5f);
  EXPECT_FLOAT_EQ(lower.y(), -1.0f);
}

}  // namespace

// Between the panel on the left and the plots' column on the right: the stretch between them;
// the widest stretch wins; too little anywhere, the whole view.
TEST(ViewFraming, TheWidestStretchNoWindowCovers) {
  const wobble::ViewportRegion between =
      wobble::region_free_of(1280.0f, {{20.0f, 340.0f}, {900.0f, 1280.0f}});
  EXPECT_FLOAT_EQ(between.left, 340.0f / 1280.0f);
  EXPECT_FLOAT_EQ(between.right, 900.0f / 1280.0f);
  EXPECT_FLOAT_EQ(between.top, 0.0f);
  EXPECT_FLOAT_EQ(between.bottom, 1.0f);
  // Overlapping covers, given in any order; the free part left of them is wider.
  const wobble::ViewportRegion left_part =
      wobble::region_free_of(1000.0f, {{700.0f, 1000.0f}, {500.0f, 800.0f}});
  EXPECT_FLOAT_EQ(left_part.left, 0.0f);
  EXPECT_FLOAT_EQ(left_part.right, 0.5f);
  const wobble::ViewportRegion sliver =
      wobble::region_free_of(1280.0f, {{0.0f, 680.0f}, {684.0f, 1280.0f}});
  EXPECT_FLOAT_EQ(sliver.left, 0.0f);
  EXPECT_FLOAT_EQ(sliver.right, 1.0f);
  const wobble::ViewportRegion nothing = wobble::region_free_of(1280.0f, {{5.0f, 5.0f}});
  EXPECT_FLOAT_EQ(nothing.left, 0.0f);
  EXPECT_FLOAT_EQ(nothing.right, 1.0f) << "an empty cover covers nothing";
  // The panel alone, as region_beside_panel frames it.
  const wobble::ViewportRegion panel = wobble::region_free_of(1280.0f, {{20.0f, 340.0f}});
  const wobble::ViewportRegion beside = wobble::region_beside_panel(1280.0f, 20.0f, 340.0f);
  EXPECT_FLOAT_EQ(panel.left, beside.left);
  EXPECT_FLOAT_EQ(panel.right, beside.right);
}

// A phone held upright: the open panel spans the width, so the shape is framed below it, in the
// part it leaves (the shape was framed behind the panel).
TEST(RegionBelow, BelowAPanelAsWideAsTheView) {
  const wobble::ViewportRegion below = wobble::region_below(2532.0f, 1392.0f);
  EXPECT_FLOAT_EQ(below.top, 1392.0f / 2532.0f);
  EXPECT_FLOAT_EQ(below.bottom, 1.0f);
  EXPECT_FLOAT_EQ(below.left, 0.0f);
  EXPECT_FLOAT_EQ(below.right, 1.0f);
  // Less than a third left: the whole view, behind the panel, rather than a sliver.
  const wobble::ViewportRegion whole = wobble::region_below(844.0f, 700.0f);
  EXPECT_FLOAT_EQ(whole.top, 0.0f);
  EXPECT_FLOAT_EQ(whole.bottom, 1.0f);
}

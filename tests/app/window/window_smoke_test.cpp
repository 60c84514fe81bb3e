// The real window, under a virtual X server (xvfb-run), as a user on a desktop would see it.
#include <gtest/gtest.h>

#include "../cloth_pixels.h"
#include "../run_wobble.h"
#include "io/png_image.h"

namespace {

using wobble::testing::run_wobble;
using wobble::testing::TemporaryFolder;

TEST(WindowSmoke, OpensRunsThirtyFramesAndShowsTheClothAndPanel) {
  ASSERT_EQ(std::system("command -v xvfb-run >/dev/null"), 0)
      << "xvfb-run is missing: scripts/test.sh installs it (package xvfb)";
  TemporaryFolder folder;
  const std::string shot = folder.file("window.png");
  // xvfb-run's screen is large enough for the 1280×720 window.
  const auto run = run_wobble("cloth --frames 30 --screenshot '" + shot + "'",
                              "xvfb-run -a -s '-screen 0 1600x1000x24'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const wobble::RgbaImage image = wobble::read_png(shot);
  EXPECT_EQ(image.width, 1280);
  EXPECT_EQ(image.height, 720);
  long cloth = 0, panel = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const unsigned char* p = image.pixel(x, y);
      if (wobble::testing::is_cloth_front(p)) ++cloth;  // the cloth's orange front
      // ImGui's panel background: near black, in the top-left corner.
      if (x < 300 && y < 400 && p[0] < 25 && p[1] < 25 && p[2] < 25) ++panel;
    }
  }
  const double pixels = 1280.0 * 720.0;
  EXPECT_GT(cloth / pixels, 0.05) << "the cloth is missing";
  EXPECT_GT(panel / pixels, 0.03) << "the panel is missing";
}

TEST(WindowSmoke, WithoutADisplayItPointsToHeadlessAndXvfb) {
  const auto run = run_wobble("cloth --frames 1", "DISPLAY= WAYLAND_DISPLAY=");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--headless"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("xvfb-run"), std::string::npos) << run.err;
}

}  // namespace

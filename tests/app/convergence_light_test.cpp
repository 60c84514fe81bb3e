// The convergence light as a class sees it: read from the panel as drawn (a headless `--ui
// --plots` picture at 1280 × 720, where the plots' column has its full width), not from the
// function that classifies a step. The light at rest was red twice after its classification had
// been fixed, because the panel's copy of the step's record lost the force scale the
// classification measures a step at rest by.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "io/png_image.h"
#include "run_wobble.h"
#include "ui/instrument_windows.h"

namespace {

using wobble::testing::run_wobble;
using wobble::testing::TemporaryFolder;

constexpr int width = 1280, height = 720;

// The light's three colours as drawn (instrument_windows.cpp's, in bytes).
struct Light {
  const char* name;
  int rgb[3];
};
constexpr Light lights[] = {
    {"green", {89, 217, 89}}, {"amber", {255, 184, 38}}, {"red", {255, 77, 64}}};

bool near(const unsigned char* p, const int (&rgb)[3], int tolerance) {
  for (int c = 0; c < 3; ++c) {
    if (std::abs(p[c] - rgb[c]) > tolerance) return false;
  }
  return true;
}

// Pixels of each light colour in the rows [top, bottom) of the convergence window's column.
struct Counts {
  long of[3] = {0, 0, 0};
};
Counts count_lights(const wobble::RgbaImage& image, int top, int bottom) {
  const int left = static_cast<int>(wobble::instrument_column_left(width, 1.0f));
  Counts counts;
  for (int y = top; y < bottom; ++y) {
    for (int x = left; x < image.width; ++x) {
      for (int i = 0; i < 3; ++i)
        counts.of[i] += near(image.pixel(x, y), lights[i].rgb, 12);
    }
  }
  return counts;
}

struct Shown {
  const char* light = "none";
  long light_pixels = 0;  // the disc and the words beside it
  long hint_pixels = 0;   // the hint's lines below, in any light colour
};

// The window's first line (the disc and its words) and the two lines below it (where the hint
// wraps), at ImGui's default style: title bar 19 px from y = 10, then 8 px of padding; a line is
// 17 px.
Shown shown(const std::string& arguments, long frames) {
  TemporaryFolder folder;
  const std::string image_path = folder.file("panel.png");
  const auto run =
      run_wobble(arguments + " --headless --ui --plots --frames " + std::to_string(frames) +
                     " --width " + std::to_string(width) + " --height " + std::to_string(height) +
                     " --screenshot '" + image_path + "'",
                 "DISPLAY= WAYLAND_DISPLAY=");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  const wobble::RgbaImage image = wobble::read_png(image_path);
  const int first_line = 10 + 19 + 8;
  const Counts light = count_lights(image, first_line, first_line + 15);
  const Counts hint = count_lights(image, first_line + 17, first_line + 17 + 32);
  Shown result;
  for (int i = 0; i < 3; ++i) {
    if (light.of[i] > result.light_pixels) {
      result.light_pixels = light.of[i];
      result.light = lights[i].name;
    }
    result.hint_pixels += hint.of[i];
  }
  return result;
}

TEST(ConvergenceLight, TheDefaultClothAtRestIsNotRedInThePanel) {
  // Step 600: the cloth has hung still for seconds (kinetic energy under 0.01 J).
  const Shown rest = shown("cloth", 600);
  EXPECT_NE(std::string(rest.light), "red");
  EXPECT_NE(std::string(rest.light), "none");
  EXPECT_GT(rest.light_pixels, 150) << "the disc and its words";
  // No hint unless red: nothing to fix.
  EXPECT_LT(rest.hint_pixels, 20);
}

TEST(ConvergenceLight, AStiffClothWithFewIterationsIsRedWithItsHint) {
  const Shown stiff = shown("cloth --k 100000 --iterations 5", 40);
  EXPECT_EQ(std::string(stiff.light), "red");
  EXPECT_GT(stiff.light_pixels, 150);
  EXPECT_GT(stiff.hint_pixels, 200) << "the hint under a red light";
}

}  // namespace

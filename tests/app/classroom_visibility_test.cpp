// What a class sees on a projector (issue 41), at the 1280 × 720 of one: a rope of springs
// without faces drawn thick in its material colour, a curtain's 81 pins as separate dots, and a
// tablecloth hiding the table's edge it is draped over. Each renders the real scene headless.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "../shared_constants.h"
#include "cloth_pixels.h"
#include "io/png_image.h"
#include "run_wobble.h"

namespace {

using wobble::testing::run_wobble;
using wobble::testing::TemporaryFolder;

using wobble::testing::assets;

wobble::RgbaImage render(const TemporaryFolder& folder, const std::string& scene, int frames) {
  const std::string image = folder.file("shown.png");
  const auto run = run_wobble("'" + scene + "' --headless --frames " + std::to_string(frames) +
                                  " --width 1280 --height 720 --screenshot '" + image + "'",
                              "DISPLAY= WAYLAND_DISPLAY=");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return wobble::read_png(image);
}

TEST(ClassroomVisibility, RopeIsABandSeveralPixelsWideInItsMaterialColour) {
  TemporaryFolder folder;
  const wobble::RgbaImage image = render(folder, assets + "/course/rope.json", 120);
  // The rope's material colour is the surface's default orange, which neither the background
  // nor the grid has. One-pixel lines in the springs' pale cyan had none of it.
  long rope = 0;
  std::vector<int> column_heights;
  for (int x = 0; x < image.width; ++x) {
    int height = 0;
    for (int y = 0; y < image.height; ++y)
      height += wobble::testing::is_cloth_front(image.pixel(x, y)) ? 1 : 0;
    if (height > 0) column_heights.push_back(height);
    rope += height;
  }
  // It spans about 370 columns; 6 px across, that is over 2,000 pixels.
  EXPECT_GT(rope, 1500);
  ASSERT_FALSE(column_heights.empty());
  std::nth_element(column_heights.begin(), column_heights.begin() + column_heights.size() / 2,
                   column_heights.end());
  EXPECT_GE(column_heights[column_heights.size() / 2], 5) << "the rope is not several pixels wide";
}

// Pixels of pin markers on a curtain coloured blue: red or pink fills, or near-black rims.
bool is_pin_mark(const unsigned char* p) {
  const bool reddish = p[0] > p[2] + 40 && p[0] > p[1] + 40;
  const bool black = p[0] < 22 && p[1] < 22 && p[2] < 22;
  return reddish || black;
}

// The groups of 4-connected pixels for which `inside` holds: their widths in pixels.
std::vector<int> blob_widths(const wobble::RgbaImage& image, bool (*inside)(const unsigned char*)) {
  std::vector<char> seen(static_cast<std::size_t>(image.width) * image.height, 0);
  std::vector<int> widths, stack;
  for (int start = 0; start < image.width * image.height; ++start) {
    if (seen[start] || !inside(image.pixel(start % image.width, start / image.width))) continue;
    int left = image.width, right = -1;
    seen[start] = 1;
    stack.assign(1, start);
    while (!stack.empty()) {
      const int at = stack.back();
      stack.pop_back();
      const int x = at % image.width, y = at / image.width;
      left = std::min(left, x);
      right = std::max(right, x);
      const int next[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
      for (const auto& n : next) {
        if (n[0] < 0 || n[1] < 0 || n[0] >= image.width || n[1] >= image.height) continue;
        const int index = n[1] * image.width + n[0];
        if (seen[index] || !inside(image.pixel(n[0], n[1]))) continue;
        seen[index] = 1;
        stack.push_back(index);
      }
    }
    widths.push_back(right - left + 1);
  }
  return widths;
}

TEST(ClassroomVisibility, CurtainPinsShowAsSeparateDots) {
  TemporaryFolder folder;
  // The curtain as it is, coloured blue so that the pins' red and black stand apart from it.
  std::ifstream in(assets + "/curtain.json");
  std::string scene((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t at = scene.find("\"appearance\"");
  ASSERT_NE(at, std::string::npos);
  scene.replace(at, scene.find('}', at) + 1 - at,
                "\"appearance\": {\"front_color\": [0.2, 0.35, 0.8], "
                "\"back_color\": [0.2, 0.35, 0.8]}");
  std::ofstream(folder.file("curtain.json")) << scene;
  const wobble::RgbaImage image = render(folder, folder.file("curtain.json"), 120);

  // Markers 10 px wide, 4 px apart, merged into one bar 330 px long: a single blob. Sized by
  // their spacing they leave a gap between neighbours, so most of the 81 are blobs of their own.
  const std::vector<int> widths = blob_widths(image, is_pin_mark);
  ASSERT_FALSE(widths.empty());
  EXPECT_GE(widths.size(), 60u) << "the pins run together";
  EXPECT_LT(*std::max_element(widths.begin(), widths.end()), 20) << "a bar of pins";
}

// The table's grey: neutral and light, unlike the red cloth, the background and the grid.
bool is_table(const unsigned char* p) {
  return p[0] > 100 && std::abs(p[0] - p[1]) < 20 && std::abs(p[1] - p[2]) < 25;
}

bool is_red_cloth(const unsigned char* p) {
  return p[0] > p[1] + 60 && p[0] > p[2] + 60;
}

TEST(ClassroomVisibility, TablesEdgeDoesNotShowThroughTheTablecloth) {
  TemporaryFolder folder;
  const wobble::RgbaImage image = render(folder, assets + "/tablecloth.json", 120);
  // Table pixels with cloth within 4 px above and below them lie inside the cloth: the edge it
  // is draped over, seen through the cloth's triangles where they cut across it (about 300 px
  // of dashed line). Where the table really shows (its sides, the strip the cloth leaves free)
  // it is wider than that.
  long through = 0, cloth = 0;
  for (int y = 4; y < image.height - 4; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (is_red_cloth(image.pixel(x, y))) ++cloth;
      if (!is_table(image.pixel(x, y))) continue;
      bool above = false, below = false;
      for (int d = 1; d <= 4; ++d) {
        above = above || is_red_cloth(image.pixel(x, y - d));
        below = below || is_red_cloth(image.pixel(x, y + d));
      }
      through += above && below ? 1 : 0;
    }
  }
  EXPECT_GT(cloth, 50000);  // the cloth is there, covering most of the table
  EXPECT_LE(through, 10);
}

}  // namespace

namespace {

// The highest vertex of `scene` after `frames` steps (m), read from the OBJ the run exports.
double highest_after(const TemporaryFolder& folder, const std::string& scene, int frames) {
  const std::string obj = folder.file("after.obj");
  const auto run = run_wobble("'" + scene + "' --headless --frames " + std::to_string(frames) +
                                  " --export-obj '" + obj + "'",
                              "DISPLAY= WAYLAND_DISPLAY=");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  std::ifstream in(obj);
  double highest = -1e300;
  for (std::string tag; in >> tag;) {
    if (tag == "v") {
      double x = 0.0, y = 0.0, z = 0.0;
      in >> x >> y >> z;
      highest = std::max(highest, y);
    }
    in.ignore(1 << 20, '\n');
  }
  return highest;
}

}  // namespace

// The shipped pile falls like cloth: thrown down edge first, it lands within a step or two and
// its pleats fold shut into a pile within half a second. (Pleated upright, it stood like
// cardboard for 2.5 s before it toppled, with self-collision and without.)
TEST(ClassroomVisibility, TheShippedPileFoldsWithinHalfASecondOfLanding) {
  TemporaryFolder folder;
  const std::string pile = assets + "/cloth_pile.json";
  EXPECT_GT(highest_after(folder, pile, 1), 0.95) << "it starts a metre tall";
  // 0.55 s: landed after about 0.02 s, then half a second.
  EXPECT_LT(highest_after(folder, pile, 33), 0.25) << "still standing";
}

namespace {

// The heights (px) of the runs of the panel's frames (the blue of headers, sliders, buttons and
// boxes) met going down the column x of `image` from y = top, in order.
std::vector<int> frame_runs(const wobble::RgbaImage& image, int x, int top) {
  std::vector<int> runs;
  int run = 0;
  for (int y = top; y < image.height; ++y) {
    const unsigned char* p = image.pixel(x, y);
    const bool frame = p[2] > p[0] + 20;  // the panel's background and text are grey or white
    if (frame) {
      ++run;
    } else if (run > 0) {
      runs.push_back(run);
      run = 0;
    }
  }
  if (run > 0) runs.push_back(run);
  return runs;
}

}  // namespace

// Where the panel is taller than the window, its sections scroll in a list that ends under a
// whole row: no header or slider shows cut in half at the list's foot (at 720 px the row after
// "instruments" did, until scrolled). Read from the panel as drawn, at two heights.
TEST(ClassroomVisibility, ThePanelsListEndsUnderAWholeRow) {
  for (const int height : {720, 610}) {
    TemporaryFolder folder;
    const std::string image_path = folder.file("panel.png");
    const auto run = run_wobble("--headless --ui --frames 3 --width 1280 --height " +
                                    std::to_string(height) + " --screenshot '" + image_path + "'",
                                "DISPLAY= WAYLAND_DISPLAY=");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const wobble::RgbaImage image = wobble::read_png(image_path);
    // The panel at (10, 10), its title bar 19 px tall; its rows' frames start 8 px in, their text 4
    // px further
    const std::vector<int> runs = frame_runs(image, 10 + 8 + 2, 10 + 19 + 2);
    ASSERT_GE(runs.size(), 10u) << "the panel's rows at " << height << " px";
    const int whole = *std::max_element(runs.begin(), runs.end());
    for (size_t i = 0; i < runs.size(); ++i) {
      EXPECT_GE(runs[i], whole - 1) << "row " << i << " of " << runs.size() << " is " << runs[i]
                                    << " px of " << whole << " at " << height << " px";
    }
  }
}

// --headless with images: EGL rendering with no display, as CI machines run it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>
#include <utility>

#include "cloth_pixels.h"
#include "io/png_image.h"
#include "run_wobble.h"

namespace {

using wobble::testing::run_wobble;
using wobble::testing::TemporaryFolder;

// No display at all, as on a server.
const std::string no_display = "DISPLAY= WAYLAND_DISPLAY=";

// Share of pixels with the colour of the cloth's front.
double orange_share(const wobble::RgbaImage& image) {
  long orange = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const unsigned char* p = image.pixel(x, y);
      if (wobble::testing::is_cloth_front(p)) ++orange;
    }
  }
  return static_cast<double>(orange) / (static_cast<double>(image.width) * image.height);
}

TEST(HeadlessRender, ScreenshotHasTheRequestedSizeAndShowsTheCloth) {
  TemporaryFolder folder;
  const auto run = run_wobble("cloth --headless --frames 30 --screenshot '" + folder.file("a.png") +
                                  "' --width 640 --height 480",
                              no_display);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const wobble::RgbaImage image = wobble::read_png(folder.file("a.png"));
  EXPECT_EQ(image.width, 640);
  EXPECT_EQ(image.height, 480);
  // The cloth covers a good part of the picture, and the background the rest.
  const double cloth = orange_share(image);
  EXPECT_GT(cloth, 0.05);
  EXPECT_LT(cloth, 0.6);
  // The top-left corner is background: a dark grey-blue.
  const unsigned char* corner = image.pixel(2, 2);
  EXPECT_LT(std::abs(corner[0] - corner[2]), 40);
  EXPECT_LT(corner[0], 120);
}

TEST(HeadlessRender, TwoRunsGiveIdenticalFiles) {
  TemporaryFolder folder;
  for (const char* name : {"a.png", "b.png"}) {
    const auto run = run_wobble(
        "jelly --headless --frames 25 --width 200 --height 150 "
        "--ui --screenshot '" +
            folder.file(name) + "'",
        no_display);
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }
  EXPECT_EQ(wobble::testing::read_text(folder.file("a.png")),
            wobble::testing::read_text(folder.file("b.png")));
}

TEST(HeadlessRender, BothEglPlatformsDrawTheSamePicture) {
  TemporaryFolder folder;
  for (const char* platform : {"device", "surfaceless"}) {
    const auto run = run_wobble(
        "cloth --headless --frames 10 --width 160 --height 120 "
        "--screenshot '" +
            folder.file(std::string(platform) + ".png") + "' --stats",
        no_display + " WOBBLE_EGL_PLATFORM=" + platform);
    ASSERT_EQ(run.exit_code, 0) << platform << ": " << run.err;
    EXPECT_NE(run.out.find(std::string("\"context\":\"EGL ") + platform), std::string::npos)
        << run.out;
  }
  EXPECT_EQ(wobble::read_png(folder.file("device.png")).pixels,
            wobble::read_png(folder.file("surfaceless.png")).pixels);
}

TEST(HeadlessRender, AnUnknownEglPlatformIsBadInputAndWritesNothing) {
  TemporaryFolder folder;
  const auto run =
      run_wobble("cloth --headless --frames 2 --screenshot '" + folder.file("a.png") + "'",
                 no_display + " WOBBLE_EGL_PLATFORM=wayland");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_EQ(run.err,
            "wobble: WOBBLE_EGL_PLATFORM: expected 'device' or 'surfaceless' (or unset), got "
            "'wayland'\n");
  EXPECT_TRUE(folder.entries().empty());
}

TEST(HeadlessRender, RecordWritesEveryFrameAndTheyMove) {
  TemporaryFolder folder;
  const std::string record = folder.file("frames");
  const auto run = run_wobble("cloth --headless --frames 12 --width 120 --height 90 --record '" +
                                  record + "' --screenshot '" + folder.file("last.png") + "'",
                              no_display);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(record))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  ASSERT_EQ(names.size(), 12u);
  EXPECT_EQ(names.front(), "frame_00001.png");
  EXPECT_EQ(names.back(), "frame_00012.png");
  // The cloth falls, so consecutive frames differ; the last frame is the screenshot.
  EXPECT_NE(wobble::read_png(record + "/frame_00001.png").pixels,
            wobble::read_png(record + "/frame_00012.png").pixels);
  EXPECT_EQ(wobble::read_png(record + "/frame_00012.png").pixels,
            wobble::read_png(folder.file("last.png")).pixels);
}

TEST(HeadlessRender, AStepThatFailsExitsWith1KeepingTheGoodFramesOnly) {
  TemporaryFolder folder;
  const std::string record = folder.file("frames");
  const auto run = run_wobble(
      "cloth --headless --frames 6 --width 64 --height 48 --drag 0:1e5,0,0@4-4 --record '" +
          record + "' --screenshot '" + folder.file("last.png") + "'",
      no_display);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_NE(run.err.find("frame 4"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(folder.file("last.png")));
  EXPECT_EQ(wobble::testing::sorted_names(record),
            (std::vector<std::string>{"frame_00001.png", "frame_00002.png", "frame_00003.png"}));
}

TEST(HeadlessRender, UiAddsThePanelAndFramesTheClothBesideIt) {
  TemporaryFolder folder;
  for (const std::string flag : {"", "--ui"}) {
    const auto run = run_wobble("cloth --headless --frames 5 --width 640 --height 400 " + flag +
                                    " --screenshot '" + folder.file("ui" + flag + ".png") + "'",
                                no_display);
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }
  const wobble::RgbaImage plain = wobble::read_png(folder.file("ui.png"));
  const wobble::RgbaImage with_ui = wobble::read_png(folder.file("ui--ui.png"));
  // The panel sits in the top-left corner, 10 px in and 330 px wide.
  constexpr int panel_right = 340;
  long panel = 0;
  for (int y = 0; y < plain.height; ++y) {
    for (int x = 0; x < panel_right; ++x) {
      panel += std::equal(plain.pixel(x, y), plain.pixel(x, y) + 3, with_ui.pixel(x, y)) ? 0 : 1;
    }
  }
  EXPECT_GT(panel, 20000) << "the panel is missing";
  // Without the panel the cloth is framed in the middle, reaching left of where the panel's edge
  // would be; with it, the whole cloth is framed beside the panel.
  const auto cloth_pixels = [](const wobble::RgbaImage& image, int x0, int x1) {
    long count = 0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = x0; x < x1; ++x)
        count += wobble::testing::is_cloth_front(image.pixel(x, y)) ? 1 : 0;
    }
    return count;
  };
  EXPECT_GT(cloth_pixels(plain, 0, panel_right), 1000);
  EXPECT_EQ(cloth_pixels(with_ui, 0, panel_right + 5), 0);
  EXPECT_GT(cloth_pixels(with_ui, panel_right + 5, with_ui.width), 2000);
}

// Two runs: without layer options, and asking for the springs and points.
const std::pair<std::string, std::string> plain_and_asked[] = {{"plain.png", ""},
                                                               {"asked.png", "--springs --points"}};

// Pixels of the springs layer of a mesh without faces: bands in the surface's front orange, which
// neither the background, the ground grid, the pins nor the points have.
bool is_spring(const unsigned char* p) {
  return wobble::testing::is_cloth_front(p);
}
// Pixels of the free vertices' points: light grey (0.92), brighter than the grid and background.
bool is_point(const unsigned char* p) {
  return p[0] > 200 && p[1] > 200 && p[2] > 200;
}

TEST(HeadlessRender, ASpringOnlyCourseSceneShowsItsSpringsAndMassesWithoutAsking) {
  TemporaryFolder folder;
  const std::string rope = std::string(WOBBLE_ASSETS_DIR) + "/course/rope.json";
  for (const auto& [name, layers] : plain_and_asked) {
    const auto run = run_wobble("'" + rope + "' --headless --frames 30 --width 640 --height 480 " +
                                    layers + " --screenshot '" + folder.file(name) + "'",
                                no_display);
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }
  const wobble::RgbaImage plain = wobble::read_png(folder.file("plain.png"));
  const wobble::RgbaImage asked = wobble::read_png(folder.file("asked.png"));
  EXPECT_TRUE(plain.pixels == asked.pixels) << "the layers must be on without --springs --points";

  // The rope is drawn along its length, not only its two pins: spring pixels in many columns,
  // and the ten free masses as points. (Before, only the pins showed: none of either.)
  long springs = 0, points = 0;
  int first_column = plain.width, last_column = -1;
  for (int y = 0; y < plain.height; ++y) {
    for (int x = 0; x < plain.width; ++x) {
      if (is_point(plain.pixel(x, y))) ++points;
      if (!is_spring(plain.pixel(x, y))) continue;
      ++springs;
      first_column = std::min(first_column, x);
      last_column = std::max(last_column, x);
    }
  }
  std::cout << "[ rope ] " << springs << " spring pixels in columns " << first_column << " to "
            << last_column << ", " << points << " point pixels\n";
  EXPECT_GT(springs, 200);
  EXPECT_GT(last_column - first_column, plain.width / 4) << "springs along the whole rope";
  EXPECT_GE(points, 10);
}

TEST(HeadlessRender, AMeshWithFacesStillStartsWithItsSurfaceOnly) {
  TemporaryFolder folder;
  const std::string banner = std::string(WOBBLE_ASSETS_DIR) + "/course/banner.json";
  for (const auto& [name, layers] : plain_and_asked) {
    const auto run = run_wobble("'" + banner + "' --headless --frames 5 --width 160 --height 120 " +
                                    layers + " --screenshot '" + folder.file(name) + "'",
                                no_display);
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }
  EXPECT_FALSE(wobble::read_png(folder.file("plain.png")).pixels ==
               wobble::read_png(folder.file("asked.png")).pixels)
      << "--springs --points must still add the layers to a mesh with faces";
}

TEST(HeadlessRender, BadImageRequestsAreRefusedBeforeAnyWork) {
  TemporaryFolder folder;
  const auto jpeg = run_wobble("cloth --headless --screenshot '" + folder.file("a.jpg") + "'");
  EXPECT_EQ(jpeg.exit_code, 2);
  EXPECT_NE(jpeg.err.find("must end in .png"), std::string::npos) << jpeg.err;
  const auto folderless =
      run_wobble("cloth --headless --screenshot '" + folder.file("no/a.png") + "'");
  EXPECT_EQ(folderless.exit_code, 2);
  const auto size = run_wobble("cloth --headless --width 0 --screenshot x.png");
  EXPECT_EQ(size.exit_code, 2);
  EXPECT_NE(size.err.find("--width"), std::string::npos) << size.err;
  EXPECT_TRUE(folder.entries().empty());
}

TEST(HeadlessRender, WithoutEglItExitsWithOneLineSayingWhatToInstall) {
  TemporaryFolder folder;
  // An empty vendor list makes libglvnd find no EGL driver at all.
  const auto run =
      run_wobble("cloth --headless --frames 2 --screenshot '" + folder.file("a.png") + "'",
                 no_display + " __EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("EGL"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("install libegl-mesa0"), std::string::npos) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_TRUE(folder.entries().empty());
}

// Pixels of `image` within `tolerance` of `rgb` in each channel, in the rectangle from (x0, y0) to
// (x1, y1), exclusive.
long pixels_near(const wobble::RgbaImage& image, const int (&rgb)[3], int tolerance, int x0, int y0,
                 int x1, int y1) {
  long count = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const unsigned char* p = image.pixel(x, y);
      if (std::abs(p[0] - rgb[0]) <= tolerance && std::abs(p[1] - rgb[1]) <= tolerance &&
          std::abs(p[2] - rgb[2]) <= tolerance) {
        ++count;
      }
    }
  }
  return count;
}

// wobble cloth --compare solver=local-global,solver=lbfgs --plots, as a class would show the two
// methods: the split view, and the energy plot with a second line (orange) for the right side,
// which the single view's plot has not.
TEST(HeadlessRender, SplitSolversShowBothSidesInThePlots) {
  TemporaryFolder folder;
  const auto render = [&](const std::string& name, const std::string& arguments) {
    const auto run =
        run_wobble("cloth --headless --frames 12 --plots " + arguments +
                       " --width 1280 --height 720 --screenshot '" + folder.file(name) + "'",
                   no_display);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return wobble::read_png(folder.file(name));
  };
  const wobble::RgbaImage split = render("split.png", "--compare solver=local-global,solver=lbfgs");
  const wobble::RgbaImage single = render("single.png", "");
  ASSERT_EQ(split.width, 1280);
  ASSERT_EQ(single.width, 1280);
  // The energy window stands under the convergence window in the column at the right (from
  // x = 890, y = 410 at this size; instrument_windows.cpp); the right side's line and its legend
  // swatch are the convergence window's orange, (255, 170, 90).
  const int orange[3] = {255, 170, 90};
  const long split_orange = pixels_near(split, orange, 20, 890, 410, 1280, 720);
  EXPECT_GT(split_orange, 50) << "no right-side line in the energy plot";
  EXPECT_LT(pixels_near(single, orange, 20, 890, 410, 1280, 720), split_orange / 10);
  // Left of the column, both sides show the cloth.
  long left = 0, right = 0;
  for (int y = 0; y < split.height; ++y) {
    for (int x = 0; x < 880; ++x) {
      if (wobble::testing::is_cloth_front(split.pixel(x, y))) (x < 445 ? left : right) += 1;
    }
  }
  EXPECT_GT(left, 1000);
  EXPECT_GT(right, 1000);
}

}  // namespace

// The split view shares what the panel leaves: the left side's cloth shows beside the panel as
// whole as the right side's, not under it (at 1280x720 the panel took most of the left half).
TEST(HeadlessRender, SplitViewSidesShowBesideThePanel) {
  TemporaryFolder folder;
  const auto run = run_wobble(
      "cloth --headless --frames 2 --ui --compare iterations=5 --width "
      "1280 --height 720 --screenshot '" +
          folder.file("split.png") + "'",
      no_display);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const wobble::RgbaImage image = wobble::read_png(folder.file("split.png"));
  // The line between the sides: the column that is light grey from top to bottom.
  int divider = -1;
  for (int x = 0; x < image.width && divider < 0; ++x) {
    int light = 0;
    for (int y = 0; y < image.height; ++y) {
      const unsigned char* p = image.pixel(x, y);
      if (p[0] > 200 && p[1] > 200 && p[2] > 200) ++light;
    }
    if (light > image.height * 9 / 10) divider = x;
  }
  ASSERT_GT(divider, 0) << "no line between the sides";
  // Right of the middle: the panel (about 340 wide) leaves [340, 1280), split at 810.
  EXPECT_GT(divider, image.width / 2 + 80);
  long left = 0, right = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (!wobble::testing::is_cloth_front(image.pixel(x, y))) continue;
      (x < divider ? left : right) += 1;
    }
  }
  EXPECT_GT(right, 2000);
  EXPECT_GT(left, right * 7 / 10) << "left " << left << ", right " << right;
}

// Every way the headless path can find no GPU gives one line and exit 2, never a signal.
TEST(HeadlessRender, WithoutLibEglItExitsWithOneLineNamingIt) {
  TemporaryFolder folder;
  const auto run =
      run_wobble("cloth --headless --ui --frames 2 --screenshot '" + folder.file("a.png") + "'",
                 no_display + " " + wobble::testing::hiding("libEGL.so.1"));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_EQ(run.err,
            "wobble: error: cannot create a headless OpenGL 3.3 context: libEGL.so.1 is not "
            "installed (Debian: libegl1, with libegl-mesa0 for Mesa)\n");
  EXPECT_TRUE(folder.entries().empty());
}

TEST(HeadlessRender, AnAskedPlatformThatFailsExitsWithOneLineNamingIt) {
  TemporaryFolder folder;
  for (const std::string platform : {"device", "surfaceless"}) {
    const auto run =
        run_wobble("cloth --headless --ui --frames 2 --screenshot '" + folder.file("a.png") + "'",
                   no_display + " WOBBLE_EGL_PLATFORM=" + platform +
                       " __EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json");
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_NE(run.err.find("(" + platform + ": "), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find(platform == "device" ? "surfaceless:" : "device:"), std::string::npos)
        << run.err;
  }
  EXPECT_TRUE(folder.entries().empty());
}

TEST(HeadlessRender, ThePanelDrawsWithoutLibGl) {
  // ImGui's own OpenGL backend opened libGL.so.1, which an EGL-only machine lacks: the panel
  // aborted there. Drawn through Wobble's loader, the picture is the same with it hidden.
  TemporaryFolder folder;
  for (const std::string name : {"with", "without"}) {
    const auto run = run_wobble(
        "cloth --headless --ui --plots --frames 3 --width 640 --height 400 --screenshot '" +
            folder.file(name + ".png") + "'",
        no_display + (name == "without" ? " " + wobble::testing::hiding(wobble::testing::no_libgl)
                                        : std::string()));
    ASSERT_EQ(run.exit_code, 0) << name << ": " << run.err;
  }
  EXPECT_EQ(wobble::read_png(folder.file("with.png")).pixels,
            wobble::read_png(folder.file("without.png")).pixels);
}

TEST(HeadlessRender, StatsAndVersionNameTheDriverThatDrew) {
  TemporaryFolder folder;
  const auto run = run_wobble(
      "cloth --headless --frames 2 --width 64 --height 48 --stats "
      "--screenshot '" +
          folder.file("a.png") + "'",
      no_display + " WOBBLE_EGL_PLATFORM=surfaceless");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto stats = nlohmann::json::parse(run.out.substr(run.out.rfind('{')));
  EXPECT_EQ(stats.at("egl_platform"), "surfaceless");
  // Mesa's software renderer here; NVIDIA's driver names itself as "NVIDIA Corporation".
  EXPECT_FALSE(stats.at("gl_vendor").get<std::string>().empty());
  EXPECT_NE(stats.at("gl_renderer").get<std::string>().find("llvmpipe"), std::string::npos)
      << stats.dump();
  EXPECT_EQ(stats.at("gl_version").get<std::string>().rfind("4.", 0), 0u) << stats.dump();

  const auto version = run_wobble("--version --headless", no_display);
  ASSERT_EQ(version.exit_code, 0) << version.err;
  EXPECT_EQ(version.out.rfind("wobble ", 0), 0u) << version.out;
  for (const std::string& line :
       {std::string("\nEGL platform: device\n"),
        "\nGL vendor: " + stats.at("gl_vendor").get<std::string>() + "\n",
        "\nGL renderer: " + stats.at("gl_renderer").get<std::string>() + "\n"}) {
    EXPECT_NE(version.out.find(line), std::string::npos) << version.out;
  }
  // Without --headless, the version alone: no context is made.
  EXPECT_EQ(run_wobble("--version", no_display).out.find("GL"), std::string::npos);
}

// --expect: a user's own picture compared as the goldens are.
class ExpectOption : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto run = run_wobble(
        "cloth --headless --frames 8 --width 160 --height 120 "
        "--screenshot '" +
            expected_ + "'",
        no_display);
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }
  wobble::testing::Result expect(const std::string& extra) {
    return run_wobble("cloth --headless --frames 8 --width 160 --height 120 --expect '" +
                          expected_ + "' " + extra,
                      no_display);
  }
  TemporaryFolder folder_;
  const std::string expected_ = folder_.file("expected.png");
  const std::string diff_ = folder_.file("expected.diff.png");
};

TEST_F(ExpectOption, TheSameRunMatchesWithExitZero) {
  const auto run = expect("");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "wobble: " + expected_ +
                         ": matches (0 of 19200 pixels (0.000%) differ by more than 8 beyond "
                         "anti-aliasing (allowed: 0.030%); largest difference 0 at (0, 0))\n");
  EXPECT_FALSE(std::filesystem::exists(diff_));
}

TEST_F(ExpectOption, AChangeExitsWithOneAndADifferenceImage) {
  const auto run = expect("--camera-yaw 40");
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_EQ(run.err.rfind("wobble: " + expected_ + ": does not match: ", 0), 0u) << run.err;
  EXPECT_NE(run.err.find("largest difference "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("differing pixels in red: " + diff_), std::string::npos) << run.err;
  const wobble::RgbaImage diff = wobble::read_png(diff_);
  EXPECT_EQ(diff.width, 160);
  long red = 0;
  for (int y = 0; y < diff.height; ++y) {
    for (int x = 0; x < diff.width; ++x) {
      const unsigned char* p = diff.pixel(x, y);
      red += p[0] == 255 && p[1] == 0 && p[2] == 0;
    }
  }
  EXPECT_GT(red, 100);
  // Loosened far enough, the same change passes.
  const auto loose = expect("--camera-yaw 40 --expect-tolerance 255");
  EXPECT_EQ(loose.exit_code, 0) << loose.err;
}

TEST_F(ExpectOption, AnotherSizeExitsWithOneNamingBoth) {
  const auto run = run_wobble(
      "cloth --headless --frames 8 --width 100 --height 120 --expect '" + expected_ + "'",
      no_display);
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find("the images differ in size: expected 160x120, drawn 100x120"),
            std::string::npos)
      << run.err;
}

TEST_F(ExpectOption, BadInputIsRefusedBeforeAnyWork) {
  const std::string missing = folder_.file("missing.png");
  const std::pair<std::string, std::string> cases[] = {
      {"cloth --headless --expect '" + missing + "'", "--expect: " + missing},
      {"cloth --expect '" + expected_ + "'", "--expect: compares a headless run's last frame"},
      {"cloth --headless --expect-tolerance 3", "--expect-tolerance: needs --expect"},
      {"cloth --headless --expect '" + expected_ + "' --expect-tolerance 300",
       "--expect-tolerance: expected LEVELS[,PERCENT]"},
      {"cloth --headless --expect '" + expected_ + "' --expect-tolerance 8,x",
       "--expect-tolerance: expected LEVELS[,PERCENT]"},
  };
  for (const auto& [arguments, message] : cases) {
    const auto run =
        run_wobble(arguments + " --screenshot '" + folder_.file("out.png") + "'", no_display);
    EXPECT_EQ(run.exit_code, 2) << arguments << ": " << run.err;
    EXPECT_EQ(run.err.rfind("wobble: " + message, 0), 0u) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_FALSE(std::filesystem::exists(folder_.file("out.png"))) << arguments;
  }
}

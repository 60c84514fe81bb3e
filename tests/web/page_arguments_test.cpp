// The page's address as a command line (src/app/web/page_arguments.h), natively: the same code
// the browser runs on location.search.
#include "app/web/page_arguments.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli/command_line.h"
#include "app/cli/scene_catalog.h"
#include "io/load_scene.h"

namespace {

using Arguments = std::vector<std::string>;

const Arguments catalog = {"cloth", "jelly", "/site/assets/flag.json", "/site/assets/curtain.json"};

TEST(PageArguments, ASceneAndItsSettings) {
  EXPECT_EQ(wobble::page_arguments("?scene=flag&k=2000", catalog),
            (Arguments{"wobble", "--k", "2000", "--", "/site/assets/flag.json"}));
  EXPECT_EQ(wobble::page_arguments("?scene=curtain&dt=0.01&iterations=20&frames=60&plots", catalog),
            (Arguments{"wobble", "--dt", "0.01", "--iterations", "20", "--frames", "60", "--plots",
                       "--", "/site/assets/curtain.json"}));
}

TEST(PageArguments, NoQueryOpensTheDefaultScene) {
  EXPECT_EQ(wobble::page_arguments("", catalog), (Arguments{"wobble"}));
  EXPECT_EQ(wobble::page_arguments("?", catalog), (Arguments{"wobble"}));
}

TEST(PageArguments, EscapesAreDecodedAndUnknownKeysLeftOut) {
  // An option that writes files never comes from an address.
  EXPECT_EQ(wobble::page_arguments("?screenshot=x.png&k=1%2E5e3&scene=my+scene.json", catalog),
            (Arguments{"wobble", "--k", "1.5e3", "--", "my scene.json"}));
  // A scene named like an option stays a scene.
  EXPECT_EQ(wobble::page_arguments("?scene=--help.json", catalog),
            (Arguments{"wobble", "--", "--help.json"}));
}

// A typo in a slide's link says so on the page, one line naming the address's key, and costs
// only itself: the scene opens with the settings that were right (it showed the default cloth
// with none of them, the reason only on the console, listing 2 of the scenes).
TEST(PageArguments, WhatTheAddressGotWrongIsSaidAndCostsOnlyItself) {
  const wobble::PageRequest bad_k = wobble::read_page_address("?scene=flag&k=abc&dt=0.01", catalog);
  EXPECT_EQ(bad_k.arguments, (Arguments{"wobble", "--dt", "0.01", "--", "/site/assets/flag.json"}));
  ASSERT_EQ(bad_k.refusals.size(), 1u);
  EXPECT_EQ(bad_k.refusals[0], "address: k: expected a positive finite number, got 'abc'");

  const wobble::PageRequest bad_scene =
      wobble::read_page_address("?scene=flg&iterations=5", catalog);
  EXPECT_EQ(bad_scene.arguments, (Arguments{"wobble", "--iterations", "5"}));
  ASSERT_EQ(bad_scene.refusals.size(), 1u);
  EXPECT_EQ(bad_scene.refusals[0],
            "address: scene: no scene 'flg' (the scenes: cloth, jelly, flag, curtain); opening "
            "the default");

  const wobble::PageRequest unknown = wobble::read_page_address("?scene=flag&kk=3", catalog);
  EXPECT_EQ(unknown.arguments, (Arguments{"wobble", "--", "/site/assets/flag.json"}));
  ASSERT_EQ(unknown.refusals.size(), 1u);
  EXPECT_EQ(unknown.refusals[0].rfind("address: kk: not a key of the address", 0), 0u);

  EXPECT_TRUE(
      wobble::read_page_address("?scene=flag&k=2000&plots&bench", catalog).refusals.empty());
  EXPECT_EQ(wobble::read_page_address("?iterations=0", catalog).refusals,
            (Arguments{"address: iterations: expected a whole number from 1 to 5000, got '0'"}));
}

// A link can say what the panel sets: every setting and view option the command line takes that
// writes no file, switches on with no value or 1.
TEST(PageArguments, TheAddressTakesTheCommandLinesSettings) {
  const wobble::PageRequest request = wobble::read_page_address(
      "?scene=flag&solver=lbfgs&damping=0.5&friction=0.3&wind&self-collision=1&chebyshev=0"
      "&self-collision-thickness=0.004&camera-yaw=30&wireframe=on",
      catalog);
  EXPECT_TRUE(request.refusals.empty()) << request.refusals[0];
  EXPECT_EQ(request.arguments,
            (Arguments{"wobble", "--solver", "lbfgs", "--damping", "0.5", "--friction", "0.3",
                       "--wind", "--self-collision", "--self-collision-thickness", "0.004",
                       "--camera-yaw", "30", "--wireframe", "--", "/site/assets/flag.json"}));
  EXPECT_EQ(
      wobble::read_page_address("?wind=maybe&solver=newton", catalog).refusals,
      (Arguments{"address: wind: expected no value, 1 or 0, got 'maybe'",
                 "address: solver: " + wobble::read_page_address("?solver=newton", catalog)
                                           .refusals.at(0)
                                           .substr(std::string("address: solver: ").size())}));
  EXPECT_EQ(wobble::read_page_address("?record=x", catalog).refusals.size(), 1u)
      << "an option that writes files is no key of the address";
}

// "Copy link" gives an address that opens the scene with the settings it has now: read back as
// the page reads it, the scene opens with the same values, to the last bit.
// The command line the page starts for a link's `query`; nothing when the address refuses part of
// it (the refusal is reported as a failure) or the command line refuses it.
std::optional<wobble::CommandLine> command_of_link(const std::string& query,
                                                   const std::vector<std::string>& scenes) {
  const wobble::PageRequest request = wobble::read_page_address(query, scenes);
  EXPECT_TRUE(request.refusals.empty()) << query << ": " << request.refusals[0];
  if (!request.refusals.empty()) return std::nullopt;
  std::vector<const char*> argv;
  for (const std::string& argument : request.arguments)
    argv.push_back(argument.c_str());
  std::ostringstream out;
  return wobble::parse_command_line(static_cast<int>(argv.size()), argv.data(), out);
}

TEST(PageLink, TheLinkOpensTheSceneWithItsCurrentSettings) {
  const std::vector<std::string> scenes = wobble::scene_catalog();
  int checked = 0;
  for (const std::string& source : scenes) {
    const std::string label = wobble::scene_label(source);
    if (label != "cloth" && label != "flag" && label != "banner") continue;
    const wobble::SimulationParams opened = wobble::load_scene(source).params;
    wobble::SimulationParams now = opened;
    now.k = opened.k * 1.7;
    now.dt = 0.0123;
    now.iterations = 17;
    now.wind.on = true;
    // A course scene keeps the reference's method: only k, dt, iterations and the wind change.
    if (label != "banner") {
      now.solver = "lbfgs";
      now.damping = 0.3;
      now.contact.friction = 0.2;
      now.self_collision.on = true;
      now.self_collision.thickness = 0.004;
    }
    const std::string query = wobble::page_link_query(label, opened, now);
    const std::optional<wobble::CommandLine> command = command_of_link(query, scenes);
    ASSERT_TRUE(command) << query;
    EXPECT_EQ(command->scene, source) << query;
    // As the viewer starts it: the scene's own overrides, then --k, --dt and the rest.
    const wobble::SimulationParams got =
        command->settings.applied_to(wobble::open_scene(*command).params);
    EXPECT_EQ(got.k, now.k) << query;
    EXPECT_EQ(got.dt, now.dt) << query;
    EXPECT_EQ(got.iterations, now.iterations) << query;
    EXPECT_EQ(got.solver, now.solver) << query;
    EXPECT_EQ(got.damping, now.damping) << query;
    EXPECT_EQ(got.contact.friction, now.contact.friction) << query;
    EXPECT_EQ(got.wind.on, now.wind.on) << query;
    EXPECT_EQ(got.self_collision.on, now.self_collision.on) << query;
    EXPECT_EQ(got.self_collision.thickness, now.self_collision.thickness) << query;
    EXPECT_TRUE(wobble::page_link_losses(opened, now).empty());
    // Nothing changed: the scene alone.
    EXPECT_EQ(wobble::page_link_query(label, opened, opened), "?scene=" + label);
    ++checked;
  }
  EXPECT_EQ(checked, 3) << "the built-in cloth, the flag and the course's banner";
}

// The view a link carries (issue 53: Copy link dropped the colour, the springs and the camera):
// every part of it that differs from the scene's own reaches the command line the page starts.
TEST(PageLink, TheLinkCarriesTheColourTheSwitchesAndTheCamera) {
  const std::vector<std::string> scenes = wobble::scene_catalog();
  const wobble::SimulationParams params;
  wobble::PageView view;
  view.color_by = wobble::ColorQuantity::volume;
  view.springs = true;
  view.plots = true;
  view.scene_yaw_degrees = 10.0;
  view.yaw_degrees = 42.5;
  view.scene_pitch_degrees = 20.0;
  view.pitch_degrees = 20.0;  // the scene's own: left out
  view.zoom = 1.5;
  const std::string query = wobble::page_link_query("cloth", params, params, view);
  for (const char* key :
       {"color-by=volume", "springs", "plots", "camera-yaw=42.5", "camera-zoom=1.5"}) {
    EXPECT_NE(query.find(key), std::string::npos) << key << " in " << query;
  }
  EXPECT_EQ(query.find("camera-pitch"), std::string::npos) << query;
  const std::string keys = wobble::page_link_keys(query);
  EXPECT_NE(keys.find("color-by, "), std::string::npos) << keys;
  EXPECT_NE(keys.find("camera-zoom"), std::string::npos) << keys;
  const std::optional<wobble::CommandLine> command = command_of_link(query, scenes);
  ASSERT_TRUE(command) << query;
  EXPECT_EQ(command->color_by, wobble::ColorQuantity::volume);
  EXPECT_TRUE(command->springs);
  EXPECT_TRUE(command->plots);
  EXPECT_EQ(command->camera_yaw, 42.5);
  EXPECT_FALSE(command->camera_pitch);
  EXPECT_EQ(command->camera_zoom, 1.5);
  EXPECT_TRUE(wobble::page_link_losses(params, params, view).empty());
  view.panned = true;
  EXPECT_FALSE(wobble::page_link_losses(params, params, view).empty()) << "the pan is said";
}

// What an address cannot say is said instead of dropped in silence.
TEST(PageLink, WhatTheLinkCannotCarryIsSaid) {
  wobble::SimulationParams opened;
  opened.wind.on = true;
  wobble::SimulationParams now = opened;
  now.wind.on = false;
  now.gravity.y() = 0.0;
  EXPECT_EQ(wobble::page_link_losses(opened, now), (Arguments{"wind off", "gravity"}));
}

TEST(PageArguments, TheBenchmarkIsAskedForByItsKey) {
  EXPECT_TRUE(wobble::page_wants_bench("?bench&scene=curtain&frames=120"));
  EXPECT_TRUE(wobble::page_wants_bench("?scene=curtain&bench=1"));
  EXPECT_FALSE(wobble::page_wants_bench("?scene=bench&k=2"));
  EXPECT_FALSE(wobble::page_wants_bench(""));
}

}  // namespace

// A mouse's notch in the browser (deltaY about 100 pixels, positive towards the user) is one
// notch out, as the desktop's wheel turned towards the user; it reached the camera as 100 notches
// the wrong way. A trackpad's small deltas are shares of a notch.
TEST(PageWheel, ANotchIsANotchTheDesktopsWay) {
  EXPECT_DOUBLE_EQ(wobble::page_wheel_notches(-100.0, 0), 1.0) << "up: zoom in";
  EXPECT_DOUBLE_EQ(wobble::page_wheel_notches(100.0, 0), -1.0);
  EXPECT_DOUBLE_EQ(wobble::page_wheel_notches(4.0, 0), -0.04) << "a trackpad's small delta";
  EXPECT_DOUBLE_EQ(wobble::page_wheel_notches(-3.0, 1), 1.0) << "lines";
  EXPECT_DOUBLE_EQ(wobble::page_wheel_notches(1.0, 2), -1.0) << "a page";
  EXPECT_DOUBLE_EQ(wobble::page_wheel_notches(-10000.0, 0), 5.0) << "a fling stays a few";
  EXPECT_DOUBLE_EQ(wobble::page_wheel_notches(std::nan(""), 0), 0.0);
}

namespace {

// Mistakes that cost the whole address before (the page opened the default cloth): a key given
// twice, a switch a course scene refuses, and a course scene named by its folder.
TEST(PageArguments, AKeyGivenTwiceKeepsTheLastAndSaysSo) {
  const wobble::PageRequest twice = wobble::read_page_address("?scene=flag&k=2000&k=50", catalog);
  EXPECT_EQ(twice.arguments, (Arguments{"wobble", "--k", "50", "--", "/site/assets/flag.json"}));
  EXPECT_EQ(twice.refusals, (Arguments{"address: k: given twice; the last is used"}));
  // The command line takes what is left: one --k.
  std::vector<const char*> argv;
  for (const std::string& word : twice.arguments)
    argv.push_back(word.c_str());
  std::ostringstream ignored;
  EXPECT_NO_THROW(wobble::parse_command_line(static_cast<int>(argv.size()), argv.data(), ignored));
}

TEST(PageArguments, ACourseSceneLeavesOutWhatItRefusesAndOpensWithTheRest) {
  const Arguments with_course = {"cloth", "/site/assets/flag.json",
                                 "/site/assets/course/banner.json"};
  const wobble::PageRequest banner =
      wobble::read_page_address("?scene=banner&self-collision&k=300&chebyshev", with_course);
  EXPECT_EQ(banner.arguments,
            (Arguments{"wobble", "--k", "300", "--", "/site/assets/course/banner.json"}));
  ASSERT_EQ(banner.refusals.size(), 2u);
  EXPECT_EQ(banner.refusals[0].rfind("address: self-collision: not for a course scene", 0), 0u)
      << banner.refusals[0];
  EXPECT_NE(banner.refusals[0].find("; left out"), std::string::npos) << banner.refusals[0];
  EXPECT_EQ(banner.refusals[1].rfind("address: chebyshev: not for a course scene", 0), 0u)
      << banner.refusals[1];
  // The same switch on a scene of Wobble's own is taken.
  EXPECT_TRUE(
      wobble::read_page_address("?scene=flag&self-collision", with_course).refusals.empty());
  // Named by its folder, as the site lays it out.
  const wobble::PageRequest by_folder =
      wobble::read_page_address("?scene=course/banner", with_course);
  EXPECT_TRUE(by_folder.refusals.empty());
  EXPECT_EQ(by_folder.arguments, (Arguments{"wobble", "--", "/site/assets/course/banner.json"}));
}

}  // namespace

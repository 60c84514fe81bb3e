// The page's address as a command line (src/app/web/page_arguments.h), natively: the same code
// the browser runs on location.search.
#include "app/web/page_arguments.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

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

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
  EXPECT_EQ(wobble::page_arguments("?screenshot=x.png&k=1%2E5e3&scene=my+scene", catalog),
            (Arguments{"wobble", "--k", "1.5e3", "--", "my scene"}));
  // A scene named like an option stays a scene.
  EXPECT_EQ(wobble::page_arguments("?scene=--help", catalog),
            (Arguments{"wobble", "--", "--help"}));
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

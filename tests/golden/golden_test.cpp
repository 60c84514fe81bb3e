// Golden images: each case renders headless through the real wobble executable and is compared
// with its stored PNG in tests/golden/. WOBBLE_UPDATE_GOLDEN=1 writes the renders there instead
// (scripts/update-goldens.sh): only for an intended visual change, committed with the images.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "../app/run_wobble.h"
#include "golden_cases.h"
#include "image_compare.h"

namespace {

using wobble::testing::GoldenCase;

class GoldenImage : public ::testing::TestWithParam<GoldenCase> {};

bool updating() {
  const char* update = std::getenv("WOBBLE_UPDATE_GOLDEN");
  return update != nullptr && std::string(update) == "1";
}

TEST_P(GoldenImage, MatchesStoredPng) {
  const GoldenCase& golden = GetParam();
  const std::filesystem::path output = std::filesystem::path(WOBBLE_GOLDEN_OUTPUT) / golden.name;
  std::filesystem::create_directories(output);
  const std::string actual_path = (output / "actual.png").string();
  const std::string expected_path = std::string(WOBBLE_GOLDEN_DIR) + "/" + golden.name + ".png";

  // No DISPLAY: headless must not need one.
  const wobble::testing::Result run =
      wobble::testing::run_wobble(wobble::testing::golden_arguments(golden, WOBBLE_ASSETS_DIR) +
                                      " --headless --screenshot '" + actual_path + "'",
                                  "DISPLAY=");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const wobble::RgbaImage actual = wobble::read_png(actual_path);

  if (updating()) {
    std::filesystem::copy_file(actual_path, expected_path,
                               std::filesystem::copy_options::overwrite_existing);
    std::cout << "updated " << expected_path << "\n";
    return;
  }
  ASSERT_TRUE(std::filesystem::exists(expected_path))
      << expected_path << " is missing; scripts/update-goldens.sh makes it";
  const wobble::RgbaImage expected = wobble::read_png(expected_path);
  const wobble::testing::Tolerance& tolerance = wobble::testing::golden_tolerance;
  const wobble::testing::Comparison comparison =
      wobble::testing::compare_images(expected, actual, tolerance);
  if (!comparison.matches(tolerance)) {
    const std::string diff_path = (output / "diff.png").string();
    const wobble::RgbaImage diff = wobble::testing::difference_image(expected, actual, tolerance);
    if (!diff.pixels.empty()) wobble::write_png(diff_path, diff);
    ADD_FAILURE() << golden.name << ": " << comparison.summary(tolerance) << "\n  expected "
                  << expected_path << "\n  actual   " << actual_path << "\n  diff     "
                  << diff_path;
  } else {
    std::filesystem::remove_all(output);
  }
}

INSTANTIATE_TEST_SUITE_P(golden, GoldenImage, ::testing::ValuesIn(wobble::testing::golden_cases()),
                         [](const ::testing::TestParamInfo<GoldenCase>& info) {
                           return info.param.name;
                         });

}  // namespace

// Golden images: each case renders headless through the real wobble executable, which compares
// it with its stored PNG in tests/golden/ (--expect, app/outputs/image_compare.h).
// WOBBLE_UPDATE_GOLDEN=1 writes the renders there instead (scripts/update-goldens.sh): only for
// an intended visual change, committed with the images.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "../app/run_wobble.h"
#include "golden_cases.h"

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
  std::filesystem::remove_all(output);
  std::filesystem::create_directories(output);
  const std::string actual_path = (output / "actual.png").string();
  const std::string expected_path = std::string(WOBBLE_GOLDEN_DIR) + "/" + golden.name + ".png";
  const std::string arguments = wobble::testing::golden_arguments(golden, WOBBLE_ASSETS_DIR) +
                                " --headless --screenshot '" + actual_path + "'";

  if (updating()) {
    // No DISPLAY: headless must not need one.
    const wobble::testing::Result run = wobble::testing::run_wobble(arguments, "DISPLAY=");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    std::filesystem::copy_file(actual_path, expected_path,
                               std::filesystem::copy_options::overwrite_existing);
    std::cout << "updated " << expected_path << "\n";
    return;
  }
  ASSERT_TRUE(std::filesystem::exists(expected_path))
      << expected_path << " is missing; scripts/update-goldens.sh makes it";
  // Compared by the program itself, as a user's CI compares its own pictures: --expect, with the
  // stored image copied beside the render so that the difference image lands there too. On a
  // machine without libGL.so.1, as a GPU container with only the vendor's EGL is: nothing in the
  // headless path may need it (ImGui's own OpenGL backend opened it, and the panel aborted).
  const std::string expected_copy = (output / "expected.png").string();
  std::filesystem::copy_file(expected_path, expected_copy);
  const wobble::testing::Result run =
      wobble::testing::run_wobble(arguments + " --expect '" + expected_copy + "'",
                                  "DISPLAY= " + wobble::testing::hiding(wobble::testing::no_libgl));
  EXPECT_EQ(run.exit_code, 0) << golden.name << ": " << run.err << "  stored   " << expected_path
                              << "\n  actual   " << actual_path;
  EXPECT_NE(run.err.find(": matches ("), std::string::npos) << run.err;
  if (run.exit_code == 0) std::filesystem::remove_all(output);
}

// The hiding above works: a program that opens libGL.so.1 is refused it.
TEST(GoldenImageWithoutLibGl, TheHiddenLibraryCannotBeOpened) {
  const std::string probe = std::string("'") + WOBBLE_HIDDEN_LIBRARY_PROBE + "' libGL.so.1";
  EXPECT_EQ(std::system(("DISPLAY= " + wobble::testing::hiding(wobble::testing::no_libgl) + " " +
                         probe + " >/dev/null")
                            .c_str()),
            1 << 8);
  EXPECT_EQ(std::system((probe + " >/dev/null").c_str()), 0) << "libGL.so.1 is not installed here";
}

INSTANTIATE_TEST_SUITE_P(golden, GoldenImage, ::testing::ValuesIn(wobble::testing::golden_cases()),
                         [](const ::testing::TestParamInfo<GoldenCase>& info) {
                           return info.param.name;
                         });

}  // namespace

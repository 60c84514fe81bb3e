// The golden comparison must fail when the picture really changed. These tests render a golden
// case in-process, through the same viewer and EGL path as the executable, with one thing
// changed, and check that the stored image then no longer matches.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <utility>

#include "app/cli/command_line.h"
#include "app/headless/render_offscreen.h"
#include "app/outputs/image_compare.h"
#include "app/viewer/viewer.h"
#include "golden_cases.h"

namespace {

using wobble::testing::golden_tolerance;

wobble::CommandLine parse(const std::string& arguments) {
  std::vector<std::string> words = {"wobble"};
  std::istringstream in(arguments);
  for (std::string word; in >> word;)
    words.push_back(word);
  std::vector<const char*> argv;
  for (const std::string& word : words)
    argv.push_back(word.c_str());
  std::ostringstream ignored;
  return *wobble::parse_command_line(static_cast<int>(argv.size()), argv.data(), ignored);
}

const wobble::testing::GoldenCase& golden_case(const std::string& name) {
  for (const auto& golden : wobble::testing::golden_cases()) {
    if (golden.name == name) return golden;
  }
  throw std::runtime_error("no golden case " + name);
}

// Render golden case `name` after `change` has edited its scene and settings.
template <typename Change>
wobble::RgbaImage render_changed(const std::string& name, Change change) {
  const wobble::CommandLine command = parse(golden_case(name).arguments);
  wobble::Scene scene = wobble::make_builtin_scene(command.scene);
  wobble::ViewerSettings settings = wobble::viewer_settings(command);
  change(scene, settings);
  wobble::Viewer viewer(std::move(scene), settings, wobble::builtin_scene_names());
  wobble::OffscreenOptions options;
  options.width = command.width;
  options.height = command.height;
  options.frames = *command.frames;
  options.ui = command.ui;
  return wobble::render_offscreen(viewer, options);
}

wobble::ImageComparison against_golden(const std::string& name, const wobble::RgbaImage& actual) {
  const wobble::RgbaImage expected =
      wobble::read_png(std::string(WOBBLE_GOLDEN_DIR) + "/" + name + ".png");
  const wobble::ImageComparison comparison =
      wobble::compare_images(expected, actual, golden_tolerance);
  // The margin each change clears is worth seeing when the tolerance is reconsidered.
  std::cout << "  " << name << ": " << comparison.summary(golden_tolerance) << "\n";
  return comparison;
}

TEST(GoldenSensitivity, TheUnchangedSceneMatchesInProcessToo) {
  const wobble::RgbaImage image = render_changed("cloth", [](auto&, auto&) {});
  const auto comparison = against_golden("cloth", image);
  EXPECT_TRUE(comparison.matches(golden_tolerance)) << comparison.summary(golden_tolerance);
}

// The same golden with every pixel moved `dx` right and `dy` down (the edge rows and columns
// repeated): every edge in the picture one pixel away from where it was.
wobble::RgbaImage shifted(const wobble::RgbaImage& image, int dx, int dy) {
  wobble::RgbaImage moved = image;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const unsigned char* from = image.pixel(std::clamp(x - dx, 0, image.width - 1),
                                              std::clamp(y - dy, 0, image.height - 1));
      std::copy(from, from + 4, moved.pixels.data() + 4 * (y * image.width + x));
    }
  }
  return moved;
}

wobble::RgbaImage golden_image(const std::string& name) {
  return wobble::read_png(std::string(WOBBLE_GOLDEN_DIR) + "/" + name + ".png");
}

TEST(GoldenSensitivity, EveryEdgeMovedByOnePixelPasses) {
  for (const std::string name : {"cloth", "jelly_wireframe_springs", "cloth_ui", "drape_strain"}) {
    for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}, std::pair{-1, -1}}) {
      const auto comparison = against_golden(name, shifted(golden_image(name), dx, dy));
      EXPECT_TRUE(comparison.matches(golden_tolerance))
          << name << " moved (" << dx << ", " << dy
          << "): " << comparison.summary(golden_tolerance);
    }
  }
}

TEST(GoldenSensitivity, EdgesMovedByTwoPixelsFail) {
  for (const std::string name : {"cloth", "jelly_wireframe_springs"}) {
    const auto comparison = against_golden(name, shifted(golden_image(name), 2, 0));
    EXPECT_FALSE(comparison.matches(golden_tolerance))
        << name << ": " << comparison.summary(golden_tolerance);
  }
}

TEST(GoldenSensitivity, CameraTurnedTwoDegreesFails) {
  const wobble::RgbaImage image = render_changed("cloth", [](auto&, wobble::ViewerSettings& s) {
    s.camera_yaw_degrees = 30.0f + 2.0f;  // the default yaw is 30°
  });
  const auto comparison = against_golden("cloth", image);
  EXPECT_FALSE(comparison.matches(golden_tolerance)) << comparison.summary(golden_tolerance);
}

TEST(GoldenSensitivity, StiffnessTenPercentHigherFails) {
  const wobble::RgbaImage image =
      render_changed("cloth", [](wobble::Scene& scene, auto&) { scene.params.k *= 1.1; });
  const auto comparison = against_golden("cloth", image);
  EXPECT_FALSE(comparison.matches(golden_tolerance)) << comparison.summary(golden_tolerance);
}

TEST(GoldenSensitivity, OneSpringFewerFails) {
  // Drop the spring on the jelly's front face (z = max) nearest the face's centre. Surface
  // springs lie on triangle edges, so the dark wireframe shows where its line used to be.
  const wobble::RgbaImage image =
      render_changed("jelly_wireframe_springs", [](wobble::Scene& scene, auto&) {
        const Eigen::MatrixXd& V = scene.network.V;
        Eigen::MatrixXi& E = scene.network.E;
        const double front = V.col(2).maxCoeff();
        const Eigen::RowVector3d centre(0.5 * (V.col(0).minCoeff() + V.col(0).maxCoeff()),
                                        0.5 * (V.col(1).minCoeff() + V.col(1).maxCoeff()), front);
        Eigen::Index dropped = -1;
        double nearest = 1e300;
        for (Eigen::Index e = 0; e < E.rows(); ++e) {
          if (V(E(e, 0), 2) != front || V(E(e, 1), 2) != front) continue;
          const double distance = (0.5 * (V.row(E(e, 0)) + V.row(E(e, 1))) - centre).norm();
          if (distance < nearest) {
            nearest = distance;
            dropped = e;
          }
        }
        ASSERT_GE(dropped, 0);
        E.row(dropped) = E.row(E.rows() - 1);
        E.conservativeResize(E.rows() - 1, 2);
      });
  const auto comparison = against_golden("jelly_wireframe_springs", image);
  EXPECT_FALSE(comparison.matches(golden_tolerance)) << comparison.summary(golden_tolerance);
}

}  // namespace

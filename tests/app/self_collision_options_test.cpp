// --self-collision and --self-collision-thickness: parsed, range-checked, applied to the scene
// the command line opens and refused for a course scene; --stats reports self-collision.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli/command_line.h"
#include "app/cli/scene_catalog.h"
#include "parse_words.h"
#include "run_wobble.h"
#include "sim/input_error.h"
#include "sim/value_limits.h"

namespace {

using wobble::testing::Result;
using wobble::testing::run_wobble;
using wobble::testing::TemporaryFolder;

wobble::CommandLine parse(std::vector<std::string> words) {
  return wobble::testing::parse_words(std::move(words));
}

std::string error_of(std::vector<std::string> words) {
  try {
    wobble::open_scene(parse(std::move(words)));
  } catch (const wobble::InputError& error) {
    return error.what();
  }
  return "(no error)";
}

const std::string course_scene = std::string(WOBBLE_ASSETS_DIR) + "/course/banner.json";

TEST(SelfCollisionOptions, HelpListsThem) {
  const Result result = run_wobble("--help");
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.out.find("--self-collision "), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("--self-collision-thickness"), std::string::npos);
  EXPECT_NE(result.out.find("contacts"), std::string::npos) << "--color-by's choices";
}

TEST(SelfCollisionOptions, OffUnlessAskedFor) {
  EXPECT_FALSE(parse({"cloth"}).settings.has("self-collision"));
  EXPECT_FALSE(wobble::open_scene(parse({"cloth"})).params.self_collision.on);
}

TEST(SelfCollisionOptions, TheFlagTurnsItOnWithTheScenesThickness) {
  const wobble::CommandLine command = parse({"cloth", "--self-collision"});
  EXPECT_EQ(command.settings.toggle("self-collision"), true);
  EXPECT_FALSE(command.settings.has("self-collision-thickness"));
  const wobble::Scene scene = wobble::open_scene(command);
  EXPECT_TRUE(scene.params.self_collision.on);
  EXPECT_EQ(scene.params.self_collision.thickness, 0.01);

  // A scene file's own thickness is kept.
  TemporaryFolder folder;
  std::ofstream(folder.file("thick.json"))
      << R"({"mesh": {"generator": "cloth", "resolution": 4}, "self_collision": {"thickness": 0.03}})";
  const wobble::Scene file =
      wobble::open_scene(parse({folder.file("thick.json"), "--self-collision"}));
  EXPECT_TRUE(file.params.self_collision.on);
  EXPECT_EQ(file.params.self_collision.thickness, 0.03);
}

TEST(SelfCollisionOptions, TheThicknessImpliesTheFlagAndIsRangeChecked) {
  const wobble::CommandLine command = parse({"cloth", "--self-collision-thickness", "0.002"});
  EXPECT_EQ(command.settings.number("self-collision-thickness"), 0.002);
  const wobble::Scene scene = wobble::open_scene(command);
  EXPECT_TRUE(scene.params.self_collision.on);
  EXPECT_EQ(scene.params.self_collision.thickness, 0.002);

  const std::string expected = "--self-collision-thickness: expected " +
                               wobble::expected_in(wobble::limits::self_collision_thickness) +
                               ", got '2'";
  EXPECT_EQ(error_of({"cloth", "--self-collision-thickness", "2"}), expected);
  EXPECT_EQ(error_of({"cloth", "--self-collision-thickness", "thin"}),
            "--self-collision-thickness: expected a positive finite number, got 'thin'");
}

TEST(SelfCollisionOptions, ACourseSceneRefusesIt) {
  ASSERT_EQ(wobble::open_scene(parse({course_scene})).params.gravity_model,
            wobble::GravityModel::force_per_vertex);
  EXPECT_FALSE(wobble::open_scene(parse({course_scene})).params.self_collision.on);
  EXPECT_EQ(error_of({course_scene, "--self-collision"}),
            "--self-collision: not for a course scene, which keeps the reference's behaviour (its "
            "k, dt, iterations and wind may be set)");
  EXPECT_EQ(error_of({course_scene, "--self-collision-thickness", "0.01"}),
            "--self-collision-thickness: not for a course scene, which keeps the reference's "
            "behaviour (its k, dt, iterations and wind may be set)");
}

// The real executable: exit code 2 and one line naming the option, headless, headless with an
// image (through the viewer) and in a window (refused before any window opens).
TEST(SelfCollisionOptions, ACourseSceneExitsWithCode2AndOneLine) {
  TemporaryFolder folder;
  const std::string image = folder.file("banner.png");
  for (const std::string& mode :
       std::vector<std::string>{"--headless", "--headless --screenshot '" + image + "'", ""}) {
    const Result result =
        run_wobble("'" + course_scene + "' --self-collision " + mode, "DISPLAY= ");
    EXPECT_EQ(result.exit_code, 2) << mode;
    EXPECT_NE(result.err.find("--self-collision: not for a course scene"), std::string::npos)
        << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  }
  EXPECT_FALSE(std::filesystem::exists(image));
}

nlohmann::json stats_of(const std::string& arguments) {
  const Result result = run_wobble(arguments + " --headless --stats");
  EXPECT_EQ(result.exit_code, 0) << result.err;
  std::string out = result.out;
  while (!out.empty() && out.back() == '\n')
    out.pop_back();
  return nlohmann::json::parse(out.substr(out.rfind('\n') + 1));
}

TEST(SelfCollisionOptions, StatsReportIt) {
  const nlohmann::json off = stats_of("cloth --frames 5");
  EXPECT_EQ(off["self_collision"], false);
  EXPECT_EQ(off["self_contacts"], 0);
  // Off, the term reports nothing: no figure of its own in the statistics.
  EXPECT_FALSE(off.contains("self_contact_detection_ms_median"));
  EXPECT_FALSE(off.contains("self_contact_solve_ms_median"));

  // The cloth falls onto the ground collider below it and folds over itself: self contacts.
  TemporaryFolder folder;
  std::ofstream(folder.file("fold.json")) << R"({
    "mesh": {"generator": "cloth", "resolution": 16, "size": 1.0, "height": 0.5},
    "pins": "none",
    "colliders": [{"type": "capsule", "from": [0, 0.2, -1], "to": [0, 0.2, 1], "radius": 0.05}],
    "self_collision": {"thickness": 0.02}})";
  const nlohmann::json on = stats_of("'" + folder.file("fold.json") + "' --frames 90");
  EXPECT_EQ(on["self_collision"], true);
  EXPECT_EQ(on["self_collision_thickness"], 0.02);
  // Each of the term's figures, by its name (StepTerm::report), without code for it in --stats.
  EXPECT_GT(on["self_contact_detection_ms_median"].get<double>(), 0.0);
  EXPECT_GE(on["self_contact_solve_ms_median"].get<double>(), 0.0);
  EXPECT_GE(on["self_contact_pairs_median"].get<double>(), 0.0);
  EXPECT_TRUE(on.contains("self_contact_guard_repairs_median"));
  EXPECT_TRUE(on["self_contacts"].is_number_integer());
  // The colliders' term reports its own too.
  EXPECT_TRUE(on.contains("collider_contact_time_ms_median"));
}

}  // namespace

namespace {

// A thickness wider than the mesh can keep between its layers (1.5 mean edges; the 16×16 cloth's
// edges are 1/15 m and their diagonals) is clamped: one note naming the setting, the run goes on,
// and the stats say what was kept. One it can keep gives no note.
TEST(SelfCollisionOptions, AThicknessTheMeshCannotKeepIsClampedWithANote) {
  TemporaryFolder folder;
  const auto write = [&](const std::string& name, double thickness) {
    std::ofstream(folder.file(name))
        << R"({"mesh": {"generator": "cloth", "resolution": 16, "size": 1.0, "height": 0.5},
               "pins": "none", "self_collision": {"thickness": )"
        << thickness << "}}";
    return "'" + folder.file(name) + "'";
  };
  const std::string wide = write("wide.json", 0.5), fine = write("fine.json", 0.02);
  const Result from_file = run_wobble(wide + " --headless --frames 2 --stats");
  EXPECT_EQ(from_file.exit_code, 0) << from_file.err;
  const std::string note = "wobble: note: self_collision.thickness 0.5 m is more than this mesh";
  EXPECT_NE(from_file.err.find(note), std::string::npos) << from_file.err;
  EXPECT_EQ(from_file.err.find("note:"), from_file.err.rfind("note:")) << "one note";
  const nlohmann::json stats = stats_of(wide + " --frames 2");
  EXPECT_EQ(stats["self_collision_thickness"], 0.5);
  // 1.5 times the mean edge, which lies between the grid's side (1/15 m) and its diagonal.
  const double clamped = stats["self_collision_thickness_kept"].get<double>();
  EXPECT_GT(clamped, 1.5 / 15.0);
  EXPECT_LT(clamped, 1.5 * std::sqrt(2.0) / 15.0);

  const Result from_flag = run_wobble(fine + " --headless --frames 2 --self-collision-thickness 1");
  EXPECT_EQ(from_flag.exit_code, 0) << from_flag.err;
  EXPECT_NE(from_flag.err.find("wobble: note: --self-collision-thickness 1 m is more"),
            std::string::npos)
      << from_flag.err;

  const Result kept = run_wobble(fine + " --headless --frames 2");
  EXPECT_EQ(kept.exit_code, 0);
  EXPECT_EQ(kept.err.find("thickness"), std::string::npos) << kept.err;
  EXPECT_EQ(stats_of(fine + " --frames 2")["self_collision_thickness_kept"], 0.02);
}

}  // namespace

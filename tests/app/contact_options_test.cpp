// --damping, --friction and --wind: parsed, range-checked and applied to the scene the command
// line opens (in-process; the bad-input catalogue runs the real executable).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli/command_line.h"
#include "app/cli/scene_catalog.h"
#include "parse_words.h"
#include "run_wobble.h"
#include "sim/input_error.h"

namespace {

using wobble::testing::TemporaryFolder;

wobble::CommandLine parse(std::vector<std::string> words) {
  return wobble::testing::parse_words(std::move(words));
}

std::string error_of(std::vector<std::string> words) {
  try {
    parse(std::move(words));
  } catch (const wobble::InputError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(ContactOptions, DampingAndFrictionApplyToTheScene) {
  const wobble::Scene plain = wobble::open_scene(parse({"cloth"}));
  EXPECT_EQ(plain.params.damping, 0.0);
  EXPECT_EQ(plain.params.contact.friction, 0.0);
  EXPECT_FALSE(plain.params.wind.on);

  const wobble::CommandLine command = parse({"cloth", "--damping", "0.5", "--friction", "0.3"});
  EXPECT_EQ(command.settings.number("damping"), 0.5);
  EXPECT_EQ(command.settings.number("friction"), 0.3);
  const wobble::Scene scene = wobble::open_scene(command);
  EXPECT_EQ(scene.params.damping, 0.5);
  EXPECT_EQ(scene.params.contact.friction, 0.3);
  // Zero is a value, not a refusal.
  EXPECT_EQ(wobble::open_scene(parse({"cloth", "--damping", "0"})).params.damping, 0.0);
}

TEST(ContactOptions, WindTurnsOnTheDefaultBreezeWhereTheSceneHasNoWind) {
  const wobble::Scene scene = wobble::open_scene(parse({"cloth", "--wind"}));
  const wobble::WindParams breeze = wobble::WindParams::default_breeze();
  EXPECT_TRUE(scene.params.wind.on);
  EXPECT_EQ(scene.params.wind.model, wobble::WindModel::aerodynamic);
  EXPECT_EQ(scene.params.wind.velocity, breeze.velocity);
  EXPECT_EQ(scene.params.wind.gusts, breeze.gusts);
}

TEST(ContactOptions, WindTurnsOnTheScenesOwnWind) {
  TemporaryFolder folder;
  std::ofstream(folder.file("w.json"))
      << R"({"mesh": {"generator": "cloth", "resolution": 4}, "simulation": {"wind":
             {"velocity": [0, 0, 3], "drag": 2, "on": false}}})";
  EXPECT_FALSE(wobble::open_scene(parse({folder.file("w.json")})).params.wind.on);
  const wobble::Scene scene = wobble::open_scene(parse({folder.file("w.json"), "--wind"}));
  EXPECT_TRUE(scene.params.wind.on);
  EXPECT_EQ(scene.params.wind.velocity, Eigen::Vector3d(0, 0, 3));
  EXPECT_EQ(scene.params.wind.drag, 2.0);
}

TEST(ContactOptions, WindOnACourseSceneIsTheCourseWind) {
  TemporaryFolder folder;
  std::ofstream(folder.file("tri.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::ofstream(folder.file("c.json")) << R"({"obj": "tri.obj", "b": [1], "k": 10})";
  const wobble::Scene scene = wobble::open_scene(parse({folder.file("c.json"), "--wind"}));
  EXPECT_TRUE(scene.params.wind.on);
  EXPECT_EQ(scene.params.wind.model, wobble::WindModel::course);
}

TEST(ContactOptions, OutOfRangeValuesNameTheOption) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--damping", "-1"},
       "--damping: expected a number within the limits 0 to 1000 1/s, "
       "got '-1'"},
      {{"--damping", "nan"}, "--damping: expected a number"},
      {{"--damping", "2000"}, "--damping: expected"},
      {{"--friction", "11"}, "--friction: expected a number within the limits 0 to 10, got '11'"},
      {{"--friction", "rough"}, "--friction: expected a number"},
  };
  for (const auto& [words, expected] : cases) {
    const std::string message = error_of(words);
    EXPECT_NE(message.find(expected), std::string::npos) << message;
  }
}

TEST(ContactOptions, HelpNamesTheNewOptions) {
  const wobble::testing::Result result = wobble::testing::run_wobble("--help");
  EXPECT_EQ(result.exit_code, 0);
  for (const char* option : {"--damping", "--friction", "--wind"})
    EXPECT_NE(result.out.find(option), std::string::npos) << option;
}

}  // namespace

// The scene file's "self_collision": {"thickness": ...} object: the self-collision switch's
// section and its thickness (sim/settings/built_in_settings.cpp), read by io/wobble_scene.cpp.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "io/load_scene.h"
#include "sim/input_error.h"
#include "sim/value_limits.h"
#include "temporary_folder.h"

namespace {

using wobble::testing::TemporaryFolder;

const char* const cloth = R"({"mesh": {"generator": "cloth", "resolution": 4})";

wobble::Scene load(const std::string& json) {
  TemporaryFolder folder;
  std::ofstream(folder.file("scene.json")) << json;
  return wobble::load_scene(folder.file("scene.json"));
}

// The message with the temporary folder taken off, so the test can compare all of it.
std::string self_collision_error(const std::string& json) {
  TemporaryFolder folder;
  const std::string path = folder.file("scene.json");
  std::ofstream(path) << json;
  try {
    wobble::load_scene(path);
  } catch (const wobble::InputError& error) {
    std::string message = error.what();
    if (message.rfind(path, 0) == 0) message = "scene.json" + message.substr(path.size());
    return message;
  }
  return "(no error)";
}

TEST(SceneSelfCollision, OffWithoutTheKey) {
  const wobble::Scene scene = load(std::string(cloth) + "}");
  EXPECT_FALSE(scene.params.self_collision.on);
  EXPECT_EQ(scene.params.self_collision.thickness, 0.01);
}

TEST(SceneSelfCollision, AnEmptyObjectTurnsItOnWithTheDefaultThickness) {
  const wobble::Scene scene = load(std::string(cloth) + R"(, "self_collision": {}})");
  EXPECT_TRUE(scene.params.self_collision.on);
  EXPECT_EQ(scene.params.self_collision.thickness, 0.01);
  EXPECT_TRUE(scene.notes.empty());
}

TEST(SceneSelfCollision, ReadsTheThickness) {
  const wobble::Scene scene =
      load(std::string(cloth) + R"(, "self_collision": {"thickness": 0.004}})");
  EXPECT_TRUE(scene.params.self_collision.on);
  EXPECT_EQ(scene.params.self_collision.thickness, 0.004);
}

TEST(SceneSelfCollision, ANonObjectIsAnErrorNamingTheFileAndKey) {
  EXPECT_EQ(self_collision_error(std::string(cloth) + R"(, "self_collision": true})"),
            "scene.json: self_collision: expected an object, got true");
  EXPECT_EQ(self_collision_error(std::string(cloth) + R"(, "self_collision": 0.01})"),
            "scene.json: self_collision: expected an object, got 0.01");
}

TEST(SceneSelfCollision, AThicknessThatIsNotANumberWithinLimitsIsAnError) {
  const std::string expected = "scene.json: self_collision.thickness: expected " +
                               wobble::expected_in(wobble::limits::self_collision_thickness);
  EXPECT_EQ(
      self_collision_error(std::string(cloth) + R"(, "self_collision": {"thickness": "1 cm"}})"),
      expected + ", got \"1 cm\"");
  EXPECT_EQ(self_collision_error(std::string(cloth) + R"(, "self_collision": {"thickness": 2}})"),
            expected + ", got 2");
  EXPECT_EQ(self_collision_error(std::string(cloth) + R"(, "self_collision": {"thickness": 0}})"),
            expected + ", got 0");
}

TEST(SceneSelfCollision, AnUnknownKeyIsAnError) {
  EXPECT_EQ(self_collision_error(std::string(cloth) + R"(, "self_collision": {"thicknes": 0.02}})"),
            "scene.json: self_collision.thicknes: unknown key, self_collision takes thickness");
  EXPECT_EQ(self_collision_error(std::string(cloth) +
                                 R"(, "self_collision": {"thickness": 0.02, "on": false}})"),
            "scene.json: self_collision.on: unknown key, self_collision takes thickness");
}

}  // namespace

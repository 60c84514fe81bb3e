// Issue 14's scene keys: colliders, friction, damping, the contact offset and wind, and "pins":
// "none" on every kind of shape.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "io/load_scene.h"
#include "sim/input_error.h"
#include "sim/value_limits.h"
#include "temporary_folder.h"

namespace {

using wobble::Collider;
using wobble::ColliderType;
using wobble::testing::TemporaryFolder;

const char* const cloth = R"("mesh": {"generator": "cloth", "resolution": 4})";

wobble::Scene load(const TemporaryFolder& folder, const std::string& json) {
  std::ofstream(folder.file("scene.json")) << json;
  return wobble::load_scene(folder.file("scene.json"));
}

wobble::Scene load(const std::string& json) {
  TemporaryFolder folder;
  return load(folder, json);
}

std::string contact_keys_error(const std::string& json) {
  try {
    load(json);
  } catch (const wobble::InputError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(ContactKeys, EveryColliderTypeFillsItsFields) {
  const wobble::Scene scene = load(std::string("{") + cloth + R"(, "colliders": [
      {"type": "ground"},
      {"type": "ground", "height": -0.5, "friction": 0.7},
      {"type": "plane", "point": [0, 1, 2], "normal": [0, 0, 2]},
      {"type": "sphere", "center": [1, 2, 3], "radius": 0.25},
      {"type": "box", "center": [0, -1, 0], "size": [2, 0.5, 3]},
      {"type": "capsule", "from": [-1, 0, 0], "to": [1, 0, 0], "radius": 0.1, "friction": 0}]})");
  const std::vector<Collider>& c = scene.params.contact.colliders;
  ASSERT_EQ(c.size(), 6u);
  EXPECT_EQ(c[0].type, ColliderType::ground);
  EXPECT_EQ(c[0].height, 0.0);
  EXPECT_EQ(c[0].friction, -1.0);  // the material's
  EXPECT_EQ(c[1].height, -0.5);
  EXPECT_EQ(c[1].friction, 0.7);
  EXPECT_EQ(c[2].type, ColliderType::plane);
  EXPECT_EQ(c[2].center, Eigen::Vector3d(0, 1, 2));
  // Normalized as the simulation's validation does: exact for an axis vector.
  EXPECT_EQ(c[2].normal, Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(c[3].type, ColliderType::sphere);
  EXPECT_EQ(c[3].center, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(c[3].radius, 0.25);
  EXPECT_EQ(c[4].type, ColliderType::box);
  EXPECT_EQ(c[4].center, Eigen::Vector3d(0, -1, 0));
  EXPECT_EQ(c[4].size, Eigen::Vector3d(2, 0.5, 3));
  EXPECT_EQ(c[5].type, ColliderType::capsule);
  EXPECT_EQ(c[5].from, Eigen::Vector3d(-1, 0, 0));
  EXPECT_EQ(c[5].to, Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(c[5].radius, 0.1);
  EXPECT_EQ(c[5].friction, 0.0);
}

TEST(ContactKeys, MaterialFrictionDampingOffsetAndTheirDefaults) {
  const wobble::Scene plain = load(std::string("{") + cloth + "}");
  EXPECT_TRUE(plain.params.contact.colliders.empty());
  EXPECT_EQ(plain.params.contact.friction, 0.0);
  EXPECT_EQ(plain.params.contact.offset, -1.0);  // automatic
  EXPECT_EQ(plain.params.damping, 0.0);
  EXPECT_FALSE(plain.params.wind.on);

  const wobble::Scene scene = load(std::string("{") + cloth +
                                   R"(, "material": {"friction": 0.3},
      "simulation": {"damping": 0.5, "contact_offset": 0.005}})");
  EXPECT_EQ(scene.params.contact.friction, 0.3);
  EXPECT_EQ(scene.params.damping, 0.5);
  EXPECT_EQ(scene.params.contact.offset, 0.005);
  EXPECT_TRUE(scene.notes.empty()) << scene.notes[0];
}

TEST(ContactKeys, WindObjectTurnsTheAerodynamicWindOn) {
  const wobble::Scene scene = load(std::string("{") + cloth + R"(, "simulation": {"wind":
      {"velocity": [4, 0, 1], "drag": 0.8, "lift": 0.2, "gusts": 0.4, "air_density": 1.1}}})");
  const wobble::WindParams& wind = scene.params.wind;
  EXPECT_TRUE(wind.on);
  EXPECT_EQ(wind.model, wobble::WindModel::aerodynamic);
  EXPECT_EQ(wind.velocity, Eigen::Vector3d(4, 0, 1));
  EXPECT_EQ(wind.drag, 0.8);
  EXPECT_EQ(wind.lift, 0.2);
  EXPECT_EQ(wind.gusts, 0.4);
  EXPECT_EQ(wind.air_density, 1.1);

  const wobble::Scene off =
      load(std::string("{") + cloth +
           R"(, "simulation": {"wind": {"velocity": [0, 0, 3], "on": false}}})");
  const wobble::WindParams defaults;
  EXPECT_FALSE(off.params.wind.on);
  EXPECT_EQ(off.params.wind.velocity, Eigen::Vector3d(0, 0, 3));
  EXPECT_EQ(off.params.wind.drag, defaults.drag);
  EXPECT_EQ(off.params.wind.lift, defaults.lift);
  EXPECT_EQ(off.params.wind.gusts, defaults.gusts);
  EXPECT_EQ(off.params.wind.air_density, defaults.air_density);
  EXPECT_TRUE(off.notes.empty());
  // An unknown key in the wind object stops loading, as everywhere else.
  const std::string message =
      contact_keys_error(std::string("{") + cloth +
                         R"(, "simulation": {"wind": {"velocity": [0, 0, 3], "colour": 1}}})");
  EXPECT_NE(message.find("scene.json: simulation.wind.colour: unknown key, simulation.wind takes "
                         "model, velocity, drag, lift, gusts, air_density, on"),
            std::string::npos)
      << message;
}

TEST(ContactKeys, CourseScenesGetTheCourseWindOff) {
  TemporaryFolder folder;
  std::ofstream(folder.file("tri.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::ofstream(folder.file("course.json")) << R"({"obj": "tri.obj", "b": [1], "k": 10})";
  const wobble::Scene scene = wobble::load_scene(folder.file("course.json"));
  EXPECT_EQ(scene.params.wind.model, wobble::WindModel::course);
  EXPECT_FALSE(scene.params.wind.on);
  EXPECT_EQ(scene.params.damping, 0.0);
  EXPECT_TRUE(scene.params.contact.colliders.empty());
}

TEST(ContactKeys, PinsNoneGivesNoPinsOnEveryShape) {
  TemporaryFolder folder;
  // A tetrahedron as a surface (OBJ, also filled) and as a volume (MEDIT).
  std::ofstream(folder.file("tet.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                           "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  std::ofstream(folder.file("tet.mesh")) << "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n"
                                            "0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n"
                                            "Tetrahedra\n1\n1 2 3 4 1\nEnd\n";
  const std::vector<std::string> meshes = {
      R"({"generator": "cloth", "resolution": 5})",
      R"({"generator": "cloth", "orientation": "vertical"})",
      R"({"generator": "jelly", "resolution": 2})",
      R"({"file": "tet.obj"})",
      R"({"file": "tet.obj", "fill": true, "fill_resolution": 3})",
      R"({"file": "tet.mesh"})",
  };
  for (const std::string& mesh : meshes) {
    for (const char* pins : {R"("none")", R"(["none"])"}) {
      const std::string json = R"({"mesh": )" + mesh + R"(, "pins": )" + pins + "}";
      const wobble::Scene scene = load(folder, json);
      EXPECT_TRUE(scene.pins.empty()) << json;
      EXPECT_GT(scene.network.V.rows(), 0) << json;
    }
  }
}

TEST(ContactKeys, BadValuesNameTheFileTheKeyAndWhatWasExpected) {
  const std::string top = std::string("{") + cloth + ", ";
  std::string sixty_five = "[";
  for (int i = 0; i <= wobble::limits::max_colliders; ++i)
    sixty_five += std::string(i ? ", " : "") + R"({"type": "ground"})";
  sixty_five += "]";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"("colliders": [{"type": "ground"}, {"type": "sphere", "center": [0, 0, 0], "radius": -1}])",
       "scene.json: colliders[1].radius: expected a positive number within the limits 0.0001 to "
       "10000 m, got -1"},
      {R"("colliders": {"type": "ground"})", "scene.json: colliders: expected a list of collider"},
      {R"("colliders": [3])", "scene.json: colliders[0]: expected a collider object"},
      {R"("colliders": [{"type": "cone"}])",
       "colliders[0].type: expected \"ground\", \"plane\", \"sphere\", \"box\" or \"capsule\", "
       "got \"cone\""},
      {R"("colliders": [{"height": 1}])", "colliders[0].type: missing"},
      {R"("colliders": [{"type": "sphere", "radius": 1}])",
       "colliders[0].center: missing, a sphere collider needs center, radius"},
      {R"("colliders": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 0]}])",
       "colliders[0].normal: expected a non-zero vector [x, y, z], got [0,0,0]"},
      {R"("colliders": [{"type": "box", "center": [0, 0, 0], "size": [1, 0, 1]}])",
       "colliders[0].size: expected three numbers [x, y, z], each within the limits 0.0001 to "
       "10000 m"},
      {R"("colliders": [{"type": "box", "center": [0, 0, 0], "size": [1, 1, 1], "radius": 1}])",
       "colliders[0].radius: not a key of a box collider, which takes center, size, friction"},
      {R"("colliders": [{"type": "ground", "frction": 1}])",
       "colliders[0].frction: unknown key for a ground collider, which takes height, friction"},
      {R"("colliders": [{"type": "ground", "friction": 11}])",
       "colliders[0].friction: expected a number within the limits 0 to 10, got 11"},
      {R"("colliders": [{"type": "capsule", "from": [0, 0, 0], "to": "up", "radius": 1}])",
       "colliders[0].to: expected three numbers"},
      {R"("colliders": )" + sixty_five, "colliders: 65 colliders, expected at most 64"},
      {R"("material": {"friction": -0.1})", "material.friction: expected a number within"},
      {R"("simulation": {"damping": -1})",
       "simulation.damping: expected a number within the limits 0 to 1000 1/s, got -1"},
      {R"("simulation": {"damping": "lots"})", "simulation.damping: expected a number"},
      {R"("simulation": {"contact_offset": 20})", "simulation.contact_offset: expected"},
      {R"("simulation": {"wind": [4, 0, 1]})", "simulation.wind: expected an object"},
      {R"("simulation": {"wind": {"drag": 1}})", "simulation.wind.velocity: missing"},
      {R"("simulation": {"wind": {"velocity": [4, 0, 1], "gusts": 2}})",
       "simulation.wind.gusts: expected a number within the limits 0 to 1, got 2"},
      {R"("simulation": {"wind": {"velocity": [4, 0, 1], "on": "yes"}})",
       "simulation.wind.on: expected true or false"},
      {R"("simulation": {"wind": {"velocity": [4, 0, 1e9]}})", "simulation.wind.velocity"},
  };
  for (const auto& [keys, expected] : cases) {
    const std::string message = contact_keys_error(top + keys + "}");
    EXPECT_NE(message.find(expected), std::string::npos) << keys << " -> " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace
